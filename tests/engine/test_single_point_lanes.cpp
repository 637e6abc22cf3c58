// One-point contacts that share no movable body (a colour's, a level's) solved four at a time: the
// same bits as one at a time, and the conditions of a sequential-impulse pass checked by hand on
// the velocities it leaves.

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "engine/solver/single_point_lanes.hpp"
#include "engine/solver/velocity_passes.hpp"
#include "random_colour.hpp"

namespace {
namespace test_single_point_lanes {

constexpr std::size_t kContacts = gp::test::kColourContacts;

// The colour of random_colour.hpp. Velocities, impulses and masses random, with the cases the
// lanes must keep apart: an idle contact (no impulse, a target it already meets), frictionless
// ones, and −0.0 velocities.
struct Colour : gp::test::RandomColour {
  explicit Colour(std::uint64_t seed) : RandomColour(seed) {
    for (std::size_t b = 1; b < gp::test::kColourBodies; ++b) {
      state.velocity[b] = {unit(random), unit(random)};
      state.angular_velocity[b] = unit(random);
    }
    // The bodies of the idle contact (4) at −0.0, which a lane that added a zero impulse to them
    // would turn into +0.0.
    state.velocity[9] = {-0.0, -0.0};
    state.angular_velocity[10] = -0.0;
    for (std::uint32_t i = 0; i < kContacts; ++i) {
      gp::Contact& c = set.append(1);
      c.body_a = gp::test::colour_body_a(i);
      c.body_b = gp::test::colour_body_b(i);
      const double angle = 3.0 * unit(random);
      c.normal = {std::cos(angle), std::sin(angle)};
      c.friction = i % 3 == 2 ? 0.0 : positive(random);
      gp::ContactPointState& p = set.points(c)[0];
      gp::set_arms(p, c.normal, {unit(random), unit(random)}, {unit(random), unit(random)});
      // The effective masses by hand: 1 / (1/m_A + 1/m_B + (r_A × d)²/I_A + (r_B × d)²/I_B).
      const auto effective = [&](double arm_a, double arm_b) {
        const gp::BodyInertia& m = inertia;
        return 1.0 / (m.inverse_mass[c.body_a] + m.inverse_mass[c.body_b] +
                      arm_a * arm_a * m.inverse_moment[c.body_a] +
                      arm_b * arm_b * m.inverse_moment[c.body_b]);
      };
      p.normal_mass = effective(p.normal_arm_a, p.normal_arm_b);
      p.tangent_mass = effective(p.tangent_arm_a, p.tangent_arm_b);
      p.target_normal_velocity = i == 4 ? -10.0 : 0.1 * unit(random);
      p.normal_impulse = i == 4 ? 0.0 : std::abs(unit(random));
      p.tangent_impulse = i == 4 ? 0.0 : c.friction * p.normal_impulse * unit(random);
      indices.push_back(i);
    }
  }
};

// One pass over `colour`'s contacts four at a time in runs of `runs` contacts each.
double pass_in_runs(Colour& colour, std::span<const std::size_t> runs) {
  return gp::test::pass_in_runs(colour, runs, gp::solve_single_points);
}

TEST_CASE("Independent one-point contacts four at a time are the same to the bit as one at a time",
          "[via:GD:impulse][via:DD:impulseV]") {
  if (!gp::four_lanes()) {
    WARN("no AVX2 on this CPU: the velocity passes take contacts one at a time");
    return;
  }
  gp::test::check_as_one_at_a_time<Colour>(gp::solve_single_points, [](const Colour& colour) {
    // The idle contact (4) and the static body (0) are left as they were, −0.0 included.
    CHECK(colour.set.points(colour.set[4])[0].normal_impulse == 0.0);
    CHECK(std::signbit(colour.state.velocity[9].x()));
    CHECK(std::signbit(colour.state.angular_velocity[10]));
    CHECK(colour.state.velocity[0] == gp::Vec2::Zero());
  });
}

TEST_CASE("After a pass four at a time, each contact meets its normal condition and friction cone",
          "[via:GD:impulse][via:DD:impulseV]") {
  Colour colour(42);
  std::vector<double> normal_before;
  for (const std::uint32_t i : colour.indices) {
    normal_before.push_back(colour.set.points(colour.set[i])[0].normal_impulse);
  }
  if (!gp::four_lanes()) {
    WARN("no AVX2 on this CPU: the velocity passes take contacts one at a time");
    return;
  }
  const std::size_t runs[] = {11};
  pass_in_runs(colour, runs);
  for (const std::uint32_t i : colour.indices) {
    const gp::Contact& c = colour.set[i];
    const gp::ContactPointState& p = colour.set.points(c)[0];
    INFO("contact " << i);
    // Solved last and alone on its two bodies, the normal constraint holds after the pass: the
    // point separates at least at its target speed, exactly where it pushes (v_rel·n by hand).
    const gp::Vec2 relative = colour.state.velocity[c.body_a] - colour.state.velocity[c.body_b];
    const double normal_speed = relative.dot(c.normal) +
                                colour.state.angular_velocity[c.body_a] * p.normal_arm_a -
                                colour.state.angular_velocity[c.body_b] * p.normal_arm_b;
    CHECK(p.normal_impulse >= 0.0);
    if (i == 4) continue;  // idle: separating faster than its target, untouched
    CHECK(normal_speed >= p.target_normal_velocity - 1e-12);
    if (p.normal_impulse > 0.0)
      CHECK(normal_speed == Approx(p.target_normal_velocity).margin(1e-12));
    // Friction, solved first, within the cone of the normal impulse it found.
    CHECK(std::abs(p.tangent_impulse) <= c.friction * normal_before[i]);
  }
}

}  // namespace test_single_point_lanes
}  // namespace
