#pragma once
// The bodies of a colour of contacts, for the tests of the kernels that take a colour's contacts
// four at a time, and how those tests run and compare a pass: contact i joins bodies 1 + 2i and 2 +
// 2i, but for the odd ones, whose B is static body 0, shared as a colour's contacts may share a
// static body. Eleven contacts: two groups of four and three left over.

#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "engine/core.hpp"
#include "engine/solver/contact_set.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace gp::test {

/// Contacts in the colour.
constexpr std::size_t kColourContacts = 11;
/// Bodies: the static one, then two a contact.
constexpr std::size_t kColourBodies = 1 + 2 * kColourContacts;

/// Contact i's A and B.
inline BodyId colour_body_a(std::uint32_t i) {
  return 1 + 2 * i;
}
inline BodyId colour_body_b(std::uint32_t i) {
  return i % 2 == 1 ? 0 : 2 + 2 * i;
}

/// The colour's bodies' inverse masses [1/kg] and moments [1/(kg·m²)]: random from 0.2 to 3, but
/// body 0's, 0 (static).
inline BodyInertia random_colour_inertia(std::mt19937_64& random) {
  std::uniform_real_distribution<double> positive(0.2, 3.0);
  BodyInertia inertia;
  inertia.inverse_mass.assign(kColourBodies, 0.0);
  inertia.inverse_moment.assign(kColourBodies, 0.0);
  for (std::size_t b = 1; b < kColourBodies; ++b) {
    inertia.inverse_mass[b] = positive(random);
    inertia.inverse_moment[b] = positive(random);
  }
  return inertia;
}

/// What a test's colour holds: the random numbers it is drawn from, its bodies' inertias
/// (random_colour_inertia) and states, and its contacts, `indices` into `set`.
struct RandomColour {
  explicit RandomColour(std::uint64_t seed) : random(seed), inertia(random_colour_inertia(random)) {
    state.resize(kColourBodies);
  }

  std::mt19937_64 random;
  std::uniform_real_distribution<double> unit{-1.0, 1.0};
  std::uniform_real_distribution<double> positive{0.2, 3.0};
  BodyInertia inertia;
  MotionState state;
  ContactSet set;
  std::vector<std::uint32_t> indices;
};

/// Runs a colour's blocks of contacts may be handed out in: starting and ending anywhere, of one
/// to eleven contacts, the last of four lanes or fewer.
inline const std::vector<std::vector<std::size_t>> kColourRuns{{11}, {3, 8}, {1, 2, 6, 2}, {7, 4}};

/// One pass over `colour`'s contacts by `solve_lanes(set, contacts, inertia, state)` in runs of
/// `runs` contacts each; returns the largest change.
template <typename SolveLanes>
double pass_in_runs(RandomColour& colour, std::span<const std::size_t> runs,
                    const SolveLanes& solve_lanes) {
  double largest = 0.0;
  for (std::size_t first = 0; const std::size_t run : runs) {
    largest =
        std::max(largest, solve_lanes(colour.set, std::span(colour.indices).subspan(first, run),
                                      colour.inertia, colour.state));
    first += run;
  }
  return largest;
}

/// One pass over `colour`'s contacts one at a time (solve_contact_once); returns the largest
/// change.
inline double pass_one_at_a_time(RandomColour& colour) {
  double largest = 0.0;
  for (const std::uint32_t i : colour.indices) {
    largest = std::max(largest,
                       solve_contact_once(colour.set, colour.set[i], colour.inertia, colour.state));
  }
  return largest;
}

/// The bits of a double.
inline std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

/// Checks that `lanes` and `one` hold the same velocities and impulses to the bit.
inline void check_same_bits(const RandomColour& lanes, const RandomColour& one) {
  for (std::size_t b = 0; b < lanes.state.velocity.size(); ++b) {
    CHECK(bits(lanes.state.velocity[b].x()) == bits(one.state.velocity[b].x()));
    CHECK(bits(lanes.state.velocity[b].y()) == bits(one.state.velocity[b].y()));
    CHECK(bits(lanes.state.angular_velocity[b]) == bits(one.state.angular_velocity[b]));
  }
  for (const std::uint32_t i : lanes.indices) {
    const std::span<const ContactPointState> points = lanes.set.points(lanes.set[i]);
    const std::span<const ContactPointState> reference = one.set.points(one.set[i]);
    for (std::size_t k = 0; k < points.size(); ++k) {
      INFO("contact " << i << ", point " << k);
      CHECK(bits(points[k].normal_impulse) == bits(reference[k].normal_impulse));
      CHECK(bits(points[k].tangent_impulse) == bits(reference[k].tangent_impulse));
    }
  }
}

/// For seeds 1 to 20 and each of kColourRuns: a pass over a `Colour(seed)` by `solve_lanes` in
/// those runs, and one at a time over another, which must give the same bits; then
/// `check(colour)` on the first.
template <typename Colour, typename SolveLanes, typename Check>
void check_as_one_at_a_time(const SolveLanes& solve_lanes, const Check& check) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    for (const std::vector<std::size_t>& runs : kColourRuns) {
      Colour lanes(seed);
      Colour one(seed);
      const double largest_lanes = pass_in_runs(lanes, runs, solve_lanes);
      const double largest_one = pass_one_at_a_time(one);
      INFO("seed " << seed << ", " << runs.size() << " runs");
      CHECK(bits(largest_lanes) == bits(largest_one));
      check_same_bits(lanes, one);
      check(lanes);
    }
  }
}

}  // namespace gp::test
