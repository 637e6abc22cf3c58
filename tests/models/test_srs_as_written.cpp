// The SRS's equations taken as written, computed with the model functions, against closed forms:
// each test shows what an erratum of srs/errata.md costs, and that the code's reading avoids it.
// Criteria: rounding of a few operations, measured 0 to 3e-14; exact results are held to a few
// ulps (1e-15 relative), so that a change of evaluation order alone does not fail them.
#include <catch2/catch.hpp>
#include <vector>

#include "gamephysics/models.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;

namespace {
namespace test_srs_as_written {

TEST_CASE("SRS: IM:col2D as written doubles the kinetic energy of an elastic head-on hit",
          "[srs][IM:col2D][GD:impulse]") {
  // Equal masses, C_R = 1, A at rest, B approaching along n (from B towards A) at speed u. By hand:
  // j = 2 u / (2/m) = m u, so A leaves at u while B, which the SRS does not change, keeps u.
  const double m = 56.2, u = 2.51, ke_before = 0.5 * m * u * u;
  const Vec2 n{1.0, 0.0};
  const auto truncated = [&](const Vec2& va, const Vec2& vb) {
    const double j = gp::gd::collision_impulse(1.0, gp::dd::relative_velocity(va, vb), n, 1.0 / m,
                                               1.0 / m, 0.0, 0.0, Vec2::Zero(), Vec2::Zero());
    const Vec2 va_after = va + gp::dd::velocity_change_from_impulse(j * n, 1.0 / m);
    return std::vector<Vec2>{va_after, vb};
  };
  const auto energy = [&](const std::vector<Vec2>& v) {
    return gp::dd::kinetic_energy(m, v[0], 0.0, 0.0) + gp::dd::kinetic_energy(m, v[1], 0.0, 0.0);
  };
  const auto lab = truncated(Vec2::Zero(), Vec2{u, 0.0});
  CHECK_THAT(energy(lab), WithinRel(2.0 * ke_before, 1e-15));
  CHECK_THAT((m * (lab[0] + lab[1])).x(), WithinRel(2.0 * m * u, 1e-15));  // momentum doubles
  // In B's rest frame the same collision loses all the energy: the result depends on the frame.
  const auto moving = truncated(Vec2{-u, 0.0}, Vec2::Zero());
  CHECK_THAT(energy(moving), WithinAbs(0.0, 1e-12));
  // IM:col2D as implemented (both bodies, Newton's third law) exchanges the velocities instead.
  const gp::im::CollidingBody a{1.0 / m, 0.0, Vec2::Zero(), 0.0, Vec2::Zero()};
  const gp::im::CollidingBody b{1.0 / m, 0.0, Vec2{u, 0.0}, 0.0, Vec2::Zero()};
  const auto r = gp::im::collision_response(a, b, n, 1.0);
  CHECK_THAT(gp::dd::kinetic_energy(m, r.velocity_a, 0.0, 0.0) +
                 gp::dd::kinetic_energy(m, r.velocity_b, 0.0, 0.0),
             WithinRel(ke_before, 1e-15));
}

TEST_CASE("SRS: the direction of n decides the sign of j, and the SRS never gives it",
          "[srs][GD:impulse][IM:col2D]") {
  // A (right) and B (left) approach along x; the contact is central. GD:impulse is odd in n, so
  // j n is the same for n and −n, but only n from B towards A gives the j > 0 of IM:col2D.
  const Vec2 va{-1.0, 0.0}, vb{2.0, 0.0}, from_b_to_a{1.0, 0.0};
  const auto j = [&](const Vec2& n) {
    return gp::gd::collision_impulse(0.5, gp::dd::relative_velocity(va, vb), n, 1.0, 0.5, 0.0, 0.0,
                                     Vec2::Zero(), Vec2::Zero());
  };
  // By hand: j = 1.5 · 3 / 1.5 = 3 N·s.
  CHECK_THAT(j(from_b_to_a), WithinRel(3.0, 1e-15));
  CHECK_THAT(j(-from_b_to_a), WithinRel(-3.0, 1e-15));
  // The code reads n from B towards A; with the other direction it sees separating bodies.
  const gp::im::CollidingBody a{1.0, 0.0, va, 0.0, Vec2::Zero()};
  const gp::im::CollidingBody b{0.5, 0.0, vb, 0.0, Vec2::Zero()};
  CHECK_THAT(gp::im::collision_response(a, b, from_b_to_a, 0.5).impulse, WithinRel(3.0, 1e-15));
  CHECK(gp::im::collision_response(a, b, -from_b_to_a, 0.5).impulse == 0.0);
}

TEST_CASE("SRS: m g h with the surface g misstates a fall through the inverse-square field",
          "[srs][DD:potEnergy][GD:accelGravity]") {
  // A fall from R + h to R in GD:accelGravity's field releases G M m (1/R − 1/(R + h)) (the
  // potential −G M m / r); DD:potEnergy with g(R) says m g h, too large by the factor 1 + h/R.
  const double G = 6.6743e-11, M = 5.9722e24, R = 6.371e6, m = 56.2;
  const Vec2 g = gp::gd::gravitational_acceleration(G, M, Vec2{0.0, R});
  for (const double h : {1.0, R}) {
    INFO("h = " << h << " m");
    const double uniform = gp::dd::potential_energy(m, g, Vec2{0.0, R + h}) -
                           gp::dd::potential_energy(m, g, Vec2{0.0, R});
    const double exact = G * M * m * (1.0 / R - 1.0 / (R + h));
    // The 1 m drop subtracts two energies of 3.5e9 J: cancellation leaves about 1e-10.
    CHECK_THAT(uniform / exact, WithinRel(1.0 + h / R, 1e-9));
  }
}

TEST_CASE("SRS: τ = I α about an axis other than the centre of mass turns a body it cannot turn",
          "[srs][IM:rotMot][DD:momentOfInertia][DD:torque]") {
  // A free dumbbell (two particles m at x = ±L/2) pushed at its centre of mass: the force's line
  // passes through the centre of mass, so the body only translates (α = 0, by symmetry).
  const double m = 56.2, L = 0.412, f = 98.1;
  const std::vector<double> masses{m, m};
  const std::vector<Vec2> particles{{-L / 2, 0.0}, {L / 2, 0.0}};
  const Vec2 force{0.0, f}, centre = Vec2::Zero(), end = particles[0];
  const auto alpha_about = [&](const Vec2& axis) {
    return gp::im::angular_acceleration(gp::dd::torque(centre - axis, force),
                                        gp::dd::moment_of_inertia(masses, particles, axis));
  };
  CHECK(alpha_about(centre) == 0.0);
  // About one particle, the SRS's words ("the axis of rotation") allow, τ = f L/2 and I = m L²:
  // α = f / (2 m L), a rotation that does not happen.
  CHECK_THAT(alpha_about(end), WithinRel(f / (2.0 * m * L), 1e-15));
}

}  // namespace test_srs_as_written
}  // namespace
