// Two-point contacts (a box's edge on another's) that share no movable body, a colour's, solved
// four at a time: the same bits as one at a time, through each of the block solver's paths, and
// the conditions of a sequential-impulse pass checked by hand on the velocities it leaves.

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "engine/solver/two_point_lanes.hpp"
#include "engine/solver/velocity_passes.hpp"
#include "random_colour.hpp"

namespace {
namespace test_two_point_lanes {

constexpr std::size_t kContacts = gp::test::kColourContacts;
// Contacts with a part to play: idle (no impulse, both targets met), with a block marked not
// solvable, and with a block none of whose four cases holds.
constexpr std::uint32_t kIdle = 4;
constexpr std::uint32_t kNotSolvable = 7;
constexpr std::uint32_t kNoCase = 9;

// v_rel·n at a point of arms r_A × n and r_B × n, by hand from the bodies' velocities.
double normal_speed(const gp::MotionState& s, const gp::Contact& c, double arm_a, double arm_b) {
  const gp::Vec2 relative = s.velocity[c.body_a] - s.velocity[c.body_b];
  return relative.dot(c.normal) + s.angular_velocity[c.body_a] * arm_a -
         s.angular_velocity[c.body_b] * arm_b;
}

// The colour of random_colour.hpp, each contact with two points and its block worked by hand.
struct Colour : gp::test::RandomColour {
  explicit Colour(std::uint64_t seed) : RandomColour(seed) {
    for (std::size_t b = 1; b < gp::test::kColourBodies; ++b) {
      state.velocity[b] = {unit(random), unit(random)};
      state.angular_velocity[b] = unit(random);
    }
    // The idle contact's bodies at −0.0, which a lane that added a zero impulse to them would
    // turn into +0.0.
    state.velocity[gp::test::colour_body_a(kIdle)] = {-0.0, -0.0};
    state.angular_velocity[gp::test::colour_body_b(kIdle)] = -0.0;
    for (std::uint32_t i = 0; i < kContacts; ++i) {
      gp::Contact& c = set.append(2);
      c.body_a = gp::test::colour_body_a(i);
      c.body_b = gp::test::colour_body_b(i);
      const double angle = 3.0 * unit(random);
      c.normal = {std::cos(angle), std::sin(angle)};
      c.friction = i % 3 == 2 || i == kNoCase ? 0.0 : positive(random);
      const gp::BodyInertia& m = inertia;
      // 1 / (1/m_A + 1/m_B + (r_A × d)²/I_A + (r_B × d)²/I_B).
      const auto effective = [&](double arm_a, double arm_b) {
        return 1.0 / (m.inverse_mass[c.body_a] + m.inverse_mass[c.body_b] +
                      arm_a * arm_a * m.inverse_moment[c.body_a] +
                      arm_b * arm_b * m.inverse_moment[c.body_b]);
      };
      for (gp::ContactPointState& p : set.points(c)) {
        gp::set_arms(p, c.normal, {unit(random), unit(random)}, {unit(random), unit(random)});
        p.normal_mass = effective(p.normal_arm_a, p.normal_arm_b);
        p.tangent_mass = effective(p.tangent_arm_a, p.tangent_arm_b);
        p.target_normal_velocity = i == kIdle ? -10.0 : 0.1 * unit(random);
        p.normal_impulse = i == kIdle || i == kNoCase ? 0.0 : std::abs(unit(random));
        p.tangent_impulse =
            i == kIdle || i == kNoCase ? 0.0 : c.friction * p.normal_impulse * unit(random);
      }
      const gp::ContactPointState& p = set.points(c)[0];
      const gp::ContactPointState& q = set.points(c)[1];
      // K by hand: its diagonal GD:impulse's denominators, its coupling through both bodies
      // (n · n = 1), and its inverse where Box2D's bound on the condition number allows.
      gp::NormalBlock& k = set.block(c);
      k.k11 = 1.0 / p.normal_mass;
      k.k22 = 1.0 / q.normal_mass;
      k.k12 = m.inverse_mass[c.body_a] + m.inverse_mass[c.body_b] +
              m.inverse_moment[c.body_a] * p.normal_arm_a * q.normal_arm_a +
              m.inverse_moment[c.body_b] * p.normal_arm_b * q.normal_arm_b;
      const double det = k.k11 * k.k22 - k.k12 * k.k12;
      k.inverse11 = k.k22 / det;
      k.inverse12 = -k.k12 / det;
      k.inverse22 = k.k11 / det;
      if (i == kNotSolvable || k.k11 * k.k11 >= 1000.0 * det) {
        k.inverse11 = k.inverse12 = k.inverse22 = 0.0;
      }
      if (i == kNoCase) {
        // Not a K of any bodies: coupled −100 with unit inverses, and b = (1, −0.9), which no
        // case meets: both (x = y = −0.1), the first (x = −m_p), the second (y = 0.9 m_q, with
        // −100 y + 1 < 0 for any m_q of these bodies, at least 1/18 kg), neither (b_y < 0).
        k = {.k11 = 1.0,
             .k12 = -100.0,
             .k22 = 1.0,
             .inverse11 = 1.0,
             .inverse12 = 1.0,
             .inverse22 = 1.0};
        gp::ContactPointState& first = set.points(c)[0];
        gp::ContactPointState& second = set.points(c)[1];
        first.target_normal_velocity =
            normal_speed(state, c, first.normal_arm_a, first.normal_arm_b) - 1.0;
        second.target_normal_velocity =
            normal_speed(state, c, second.normal_arm_a, second.normal_arm_b) + 0.9;
      }
      indices.push_back(i);
    }
  }
};

// One pass over `colour`'s contacts four at a time in runs of `runs` contacts each.
double pass_in_runs(Colour& colour, std::span<const std::size_t> runs) {
  return gp::test::pass_in_runs(colour, runs, gp::solve_two_points);
}

TEST_CASE("Independent two-point contacts four at a time are the same to the bit as one at a time",
          "[via:GD:impulse][via:DD:impulseV]") {
  if (!gp::four_lanes()) {
    WARN("no AVX2 on this CPU: the velocity passes take contacts one at a time");
    return;
  }
  gp::test::check_as_one_at_a_time<Colour>(gp::solve_two_points, [](const Colour& colour) {
    // The idle contact and the static body (0) are left as they were, −0.0 included.
    CHECK(colour.set.points(colour.set[kIdle])[0].normal_impulse == 0.0);
    CHECK(std::signbit(colour.state.velocity[gp::test::colour_body_a(kIdle)].x()));
    CHECK(std::signbit(colour.state.angular_velocity[gp::test::colour_body_b(kIdle)]));
    CHECK(colour.state.velocity[0] == gp::Vec2::Zero());
  });
}

TEST_CASE("After a pass four at a time, each two-point contact meets its normal conditions",
          "[via:GD:impulse][via:DD:impulseV]") {
  Colour colour(42);
  std::vector<double> normal_before;
  for (const std::uint32_t i : colour.indices) {
    for (const gp::ContactPointState& p : colour.set.points(colour.set[i])) {
      normal_before.push_back(p.normal_impulse);
    }
  }
  if (!gp::four_lanes()) {
    WARN("no AVX2 on this CPU: the velocity passes take contacts one at a time");
    return;
  }
  const std::size_t runs[] = {kContacts};
  pass_in_runs(colour, runs);
  for (const std::uint32_t i : colour.indices) {
    if (i == kIdle) continue;  // separating faster than its targets, untouched
    const gp::Contact& c = colour.set[i];
    const std::span<const gp::ContactPointState> points = colour.set.points(c);
    INFO("contact " << i);
    // Where the block serves, both normal constraints hold together after the pass, as the last
    // solved on the two bodies (v_rel·n by hand); else the second point's, solved last, holds.
    const bool block = colour.set.block(c).solvable() && i != kNoCase;
    for (std::size_t k = block ? 0 : 1; k < 2; ++k) {
      const gp::ContactPointState& p = points[k];
      const double speed = normal_speed(colour.state, c, p.normal_arm_a, p.normal_arm_b);
      INFO("point " << k);
      CHECK(p.normal_impulse >= 0.0);
      CHECK(speed >= p.target_normal_velocity - 1e-12);
      if (p.normal_impulse > 0.0) CHECK(speed == Approx(p.target_normal_velocity).margin(1e-12));
    }
    // Friction, solved first, within the cone of each point's normal impulse before the pass.
    for (std::size_t k = 0; k < 2; ++k) {
      CHECK(std::abs(points[k].tangent_impulse) <= c.friction * normal_before[2 * i + k]);
    }
  }
  // Solved one by one, the contact with no case of the block pushes at its second point alone,
  // which closed 0.9 m/s faster than its target, while its first separated 1 m/s faster.
  CHECK(colour.set.points(colour.set[kNoCase])[0].normal_impulse == 0.0);
  CHECK(colour.set.points(colour.set[kNoCase])[1].normal_impulse > 0.0);
}

}  // namespace test_two_point_lanes
}  // namespace
