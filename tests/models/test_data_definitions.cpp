// DD checks against closed forms (rolling wheel, thin rod, free fall, bounce heights), against
// hand computations from the SRS's reasonable values, and against their defining relations.
// Criteria: rounding of a few operations, measured 0 to 3e-14; exact results are held to a few
// ulps (1e-15 relative), so that a change of evaluation order alone does not fail them.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gamephysics/models.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;

namespace {
namespace test_data_definitions {

constexpr double pi = std::numbers::pi;

TEST_CASE("Centre of mass of two particles and of a symmetric set", "[DD:ctrOfMass]") {
  // 1 kg at x = 0 and 3 kg at x = 4: the balance point is at x = 3 (lever rule, 1·3 = 3·1).
  const std::array<double, 2> m{1.0, 3.0};
  const std::array<Vec2, 2> p{Vec2{0.0, 0.0}, Vec2{4.0, 0.0}};
  CHECK_THAT((gp::dd::center_of_mass(m, p) - Vec2{3.0, 0.0}).norm(), WithinAbs(0.0, 1e-15));
  // Equal masses at the corners of a square centred at (0.412, -1): the centre.
  const std::array<double, 4> mq{56.2, 56.2, 56.2, 56.2};
  const std::array<Vec2, 4> pq{Vec2{-0.588, -2}, Vec2{1.412, -2}, Vec2{1.412, 0}, Vec2{-0.588, 0}};
  CHECK_THAT((gp::dd::center_of_mass(mq, pq) - Vec2{0.412, -1.0}).norm(), WithinAbs(0, 1e-14));
}

TEST_CASE("Moment of inertia of a ring and of a thin rod match the continuum closed forms",
          "[DD:momentOfInertia]") {
  constexpr int n = 1000;
  std::array<double, n> m{};
  std::array<Vec2, n> p{};
  // Ring of mass M and radius R about its centre: I = M R².
  const double M = 56.2, R = 0.412;
  for (int j = 0; j < n; ++j) {
    m[j] = M / n;
    p[j] = R * Vec2{std::cos(2 * pi * j / n), std::sin(2 * pi * j / n)};
  }
  CHECK_THAT(gp::dd::moment_of_inertia(m, p, Vec2::Zero()), WithinRel(M * R * R, 1e-14));
  // Thin rod of length L about its centre: I = M L² / 12 (midpoint rule error ~ 1/n²).
  const double L = 44.2;
  for (int j = 0; j < n; ++j) p[j] = Vec2{-L / 2 + L * (j + 0.5) / n, 0.0};
  CHECK_THAT(gp::dd::moment_of_inertia(m, p, Vec2::Zero()), WithinRel(M * L * L / 12.0, 1e-5));
  // About one end: M L² / 3 (parallel-axis theorem, I_end = I_cm + M (L/2)²).
  CHECK_THAT(gp::dd::moment_of_inertia(m, p, Vec2{-L / 2, 0.0}), WithinRel(M * L * L / 3, 1e-6));
}

TEST_CASE("Stepping with the mean-velocity rule reproduces the closed-form projectile",
          "[DD:linDisp][DD:linVel][DD:linAcc]") {
  // x(t) = x₀ + v₀ t + ½ g t², v(t) = v₀ + g t: constant acceleration makes the mean velocity
  // over each step v + ½ a h, so the composition must be exact up to rounding.
  const Vec2 g{0.0, -9.81}, x0{0.412, 0.0}, v0{2.51, 2.51};
  const double h = 1.0 / 60.0;
  Vec2 x = x0, v = v0;
  for (int k = 0; k < 600; ++k) {
    const Vec2 mean_velocity = v + gp::dd::velocity_change_from_acceleration(g, h / 2);
    x = gp::dd::displaced_position(x, gp::dd::displacement_from_velocity(mean_velocity, h));
    v += gp::dd::velocity_change_from_acceleration(g, h);
  }
  const double t = 600 * h;
  CHECK_THAT((x - (x0 + v0 * t + 0.5 * g * t * t)).norm(), WithinAbs(0.0, 1e-11));
  CHECK_THAT((v - (v0 + g * t)).norm(), WithinAbs(0.0, 1e-12));
}

TEST_CASE("Linear velocity is the rate of displacement", "[DD:linVel]") {
  // v = du/dt: the central difference of u(h) in h recovers the velocity.
  const Vec2 v{2.51, -1.0};
  const double dh = 1e-3;
  const Vec2 rate = (gp::dd::displacement_from_velocity(v, 0.5 + dh) -
                     gp::dd::displacement_from_velocity(v, 0.5 - dh)) /
                    (2 * dh);
  CHECK_THAT((rate - v).norm(), WithinAbs(0.0, 1e-13));
}

TEST_CASE("Orientation stays within 0 ≤ ϕ < 2π after any angular displacement", "[DD:angDisp]") {
  CHECK_THAT(gp::dd::rotated_orientation(1.5 * pi, pi), WithinAbs(0.5 * pi, 1e-15));
  CHECK_THAT(gp::dd::rotated_orientation(0.0, -0.1), WithinAbs(2 * pi - 0.1, 1e-15));
  CHECK(gp::dd::rotated_orientation(0.0, 2 * pi) == 0.0);
  const double tiny = gp::dd::rotated_orientation(0.0, -1e-18);
  CHECK(tiny >= 0.0);
  CHECK(tiny < 2 * pi);
  CHECK_THAT(gp::dd::rotated_orientation(pi / 2, 1000.0),
             WithinAbs(std::fmod(pi / 2 + 1000.0, 2 * pi), 1e-12));
}

TEST_CASE("Orientation near 0 and 2π: fmod's reduction, to the bit", "[DD:angDisp]") {
  // The reference: fmod's remainder, moved into [0, 2π), as the SRS's range asks.
  const auto reduced = [](double phi) {
    const double r = std::fmod(phi, 2 * pi);
    const double in_range = r < 0.0 ? r + 2 * pi : r;
    return in_range >= 2 * pi ? 0.0 : in_range;
  };
  // Sums just below 0, just below 2π, at and just past 2π and 4π, and a few turns away.
  for (const double phi :
       {-1e-300, -1e-18, -1e-9, -0.3, -(2 * pi) + 1e-12, -(2 * pi), -3 * pi, 2 * pi,
        std::nextafter(2 * pi, 10.0), 2 * pi + 1e-9, 3 * pi, std::nextafter(4 * pi, 0.0), 4 * pi,
        std::nextafter(4 * pi, 20.0), 9 * pi, -9 * pi}) {
    INFO("ϕ₀ + θ = " << phi);
    const double expected = reduced(phi);
    const double got = gp::dd::rotated_orientation(0.0, phi);
    CHECK(std::signbit(got) == std::signbit(expected));
    CHECK(got == expected);
    CHECK(got >= 0.0);
    CHECK(got < 2 * pi);
  }
}

TEST_CASE("Constant torque: stepping reproduces θ = ω₀t + ½αt²",
          "[DD:angDisp][DD:angVel][DD:angAccel]") {
  const double alpha = 200.0 / 74.5, omega0 = 2.1, h = 1.0 / 60.0;
  double phi = 0.0, omega = omega0, unwrapped = 0.0;
  for (int k = 0; k < 120; ++k) {
    const double mean_omega =
        omega + gp::dd::angular_velocity_change_from_acceleration(alpha, h / 2);
    const double theta = gp::dd::angular_displacement_from_velocity(mean_omega, h);
    phi = gp::dd::rotated_orientation(phi, theta);
    unwrapped += theta;
    omega += gp::dd::angular_velocity_change_from_acceleration(alpha, h);
  }
  const double t = 120 * h;
  const double theta_exact = omega0 * t + 0.5 * alpha * t * t;
  CHECK_THAT(unwrapped, WithinRel(theta_exact, 1e-14));
  CHECK_THAT(phi, WithinAbs(std::fmod(theta_exact, 2 * pi), 1e-13));
  CHECK_THAT(omega, WithinRel(omega0 + alpha * t, 2e-14));
}

TEST_CASE("Chasles: a wheel rolling without slipping", "[DD:chaslesThm]") {
  // A wheel of radius R turning counter-clockwise at ω rolls towards −x at speed ω R; its contact
  // point is at rest and its top moves at twice the centre's speed.
  const double R = 0.412, omega = 2.1;
  const Vec2 v_centre{-omega * R, 0.0};
  CHECK_THAT(gp::dd::point_velocity(v_centre, omega, {0.0, -R}).norm(), WithinAbs(0.0, 1e-15));
  CHECK_THAT((gp::dd::point_velocity(v_centre, omega, {0.0, R}) - 2 * v_centre).norm(),
             WithinAbs(0.0, 1e-15));
  // Pure rotation: speed ω r, perpendicular to the arm.
  const Vec2 arm{0.3, 0.4};
  const Vec2 v = gp::dd::point_velocity(Vec2::Zero(), omega, arm);
  CHECK_THAT(v.norm(), WithinRel(omega * 0.5, 1e-15));
  CHECK_THAT(v.dot(arm), WithinAbs(0.0, 1e-15));
}

TEST_CASE("Torque of a force: lever arm times perpendicular force, counter-clockwise positive",
          "[DD:torque]") {
  // Hand computation: 0.412 m × 98.1 N = 40.4172 N·m.
  CHECK_THAT(gp::dd::torque({0.412, 0.0}, {0.0, 98.1}), WithinRel(40.4172, 1e-15));
  CHECK_THAT(gp::dd::torque({0.412, 0.0}, {0.0, -98.1}), WithinRel(-40.4172, 1e-15));
  CHECK(gp::dd::torque({0.412, 0.0}, {98.1, 0.0}) == 0.0);  // a force through the pivot
  // Only the perpendicular component counts: 30° off the arm gives F sin 30°.
  const Vec2 f = 98.1 * Vec2{std::cos(pi / 6), std::sin(pi / 6)};
  CHECK_THAT(gp::dd::torque({0.412, 0.0}, f), WithinRel(40.4172 / 2, 2e-15));
}

TEST_CASE("Kinetic energy: reasonable values, and a rolling disc has ¾ m v²", "[DD:kEnergy]") {
  // Hand computation: ½·56.2·2.51² + ½·74.5·2.1² = 177.03281 + 164.2725 J.
  CHECK_THAT(gp::dd::kinetic_energy(56.2, {2.51, 0.0}, 74.5, 2.1),
             WithinRel(177.03281 + 164.2725, 1e-15));
  // A solid disc (I = ½ m R²) rolling at v (ω = v/R) has KE = ¾ m v².
  const double m = 56.2, R = 0.412, v = 2.51;
  CHECK_THAT(gp::dd::kinetic_energy(m, {v, 0.0}, 0.5 * m * R * R, v / R),
             WithinRel(0.75 * m * v * v, 1e-15));
}

TEST_CASE("Restitution measured from a bounce is √(h₁/h₀)", "[DD:coeffRestitution]") {
  // A ball dropped from h₀ hits the floor at √(2 g h₀) and rebounds to h₁ = C_R² h₀.
  const double g = 9.81, h0 = 44.2, h1 = 0.64 * h0;
  const Vec2 n{0.0, 1.0};
  const Vec2 before{0.0, -std::sqrt(2 * g * h0)}, after{0.0, std::sqrt(2 * g * h1)};
  CHECK_THAT(gp::dd::coefficient_of_restitution(after, before, n), WithinRel(0.8, 1e-15));
}

TEST_CASE("Relative velocity at the contact is frame independent", "[DD:reVeInColl]") {
  const Vec2 va{2.51, 0.0}, vb{-1.0, 0.5}, frame{10.0, -3.0};
  const Vec2 relative = gp::dd::relative_velocity(va, vb);
  CHECK_THAT((relative - Vec2{3.51, -0.5}).norm(), WithinAbs(0.0, 1e-15));
  CHECK_THAT((gp::dd::relative_velocity(va + frame, vb + frame) - relative).norm(),
             WithinAbs(0.0, 1e-14));
  CHECK(gp::dd::relative_velocity(va, va).norm() == 0.0);
}

TEST_CASE("Impulse of a constant force over an interval changes velocity by J/m", "[DD:impulseV]") {
  // J = ∫F dt = 98.1 N · 0.5 s = 49.05 N·s on 56.2 kg: Δv = 0.872775800711744 m/s.
  const Vec2 dv = gp::dd::velocity_change_from_impulse({49.05, 0.0}, 1.0 / 56.2);
  CHECK_THAT(dv.x(), WithinRel(0.872775800711744, 2e-15));
  CHECK_THAT(56.2 * dv.x(), WithinRel(49.05, 1e-15));  // J = m Δv as the SRS writes it
  CHECK(gp::dd::velocity_change_from_impulse({49.05, 0.0}, 0.0).norm() == 0.0);
}

TEST_CASE("Potential energy: m g h, and energy is conserved in free fall",
          "[DD:potEnergy][DD:kEnergy]") {
  const Vec2 g{0.0, -9.81};
  // Hand computation: 56.2 kg · 9.81 m/s² · 44.2 m = 24368.4324 J.
  CHECK_THAT(gp::dd::potential_energy(56.2, g, {0.412, 44.2}), WithinRel(24368.4324, 1e-15));
  // Along the closed-form projectile, KE + PE is constant.
  const Vec2 x0{0.0, 44.2}, v0{2.51, 5.0};
  const double e0 =
      gp::dd::kinetic_energy(56.2, v0, 0.0, 0.0) + gp::dd::potential_energy(56.2, g, x0);
  for (double t : {0.5, 1.0, 2.0, 3.0}) {
    const Vec2 x = x0 + v0 * t + 0.5 * g * t * t, v = v0 + g * t;
    const double e =
        gp::dd::kinetic_energy(56.2, v, 0.0, 0.0) + gp::dd::potential_energy(56.2, g, x);
    CHECK_THAT(e, WithinRel(e0, 1e-15));
  }
}

}  // namespace test_data_definitions
}  // namespace
