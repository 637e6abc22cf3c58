// IM checks: hand computations, and for IM:col2D the conservation laws of an elastic collision
// (linear momentum, angular momentum, kinetic energy with rotation) and 1D closed forms.
// Criteria: rounding of a few operations, measured 0 to 3e-14; exact results are held to a few
// ulps (1e-15 relative), so that a change of evaluation order alone does not fail them.
#include <catch2/catch.hpp>

#include "gamephysics/models.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;
using gp::im::CollidingBody;

TEST_CASE("Translational acceleration: gravity plus applied force over mass", "[IM:transMot]") {
  // Hand computation with the reasonable values: 98.1 N / 56.2 kg = 1.7455516 m/s² along x.
  const Vec2 a = gp::im::translational_acceleration({0.0, -9.81}, {98.1, 0.0}, 56.2);
  CHECK_THAT(a.x(), WithinRel(1.7455516014234873, 1e-15));
  CHECK_THAT(a.y(), WithinRel(-9.81, 1e-15));
  // A thrust equal to the weight holds a body still.
  const Vec2 hover = gp::im::translational_acceleration({0.0, -9.81}, {0.0, 56.2 * 9.81}, 56.2);
  CHECK_THAT(hover.norm(), WithinAbs(0.0, 1e-14));
}

TEST_CASE("Angular acceleration: torque over moment, of either sign", "[IM:rotMot]") {
  CHECK_THAT(gp::im::angular_acceleration(200.0, 74.5), WithinRel(2.684563758389262, 1e-15));
  // A clockwise torque gives a negative α, which the SRS's output constraint α > 0 forbids.
  CHECK(gp::im::angular_acceleration(-200.0, 74.5) < 0.0);
}

namespace {
namespace test_instance_models {
struct Totals {
  Vec2 momentum;
  double angular_momentum;  // about the origin
  double energy;
};
// Body state at the contact: centre of mass at `centre`, contact point at `centre + arm`.
Totals totals(const CollidingBody& a, const Vec2& ca, const CollidingBody& b, const Vec2& cb) {
  auto body = [](const CollidingBody& s, const Vec2& c, Totals& t) {
    const double m = 1.0 / s.inverse_mass, I = 1.0 / s.inverse_moment;
    t.momentum += m * s.velocity;
    t.angular_momentum += m * gp::cross(c, s.velocity) + I * s.angular_velocity;
    t.energy += gp::dd::kinetic_energy(m, s.velocity, I, s.angular_velocity);
  };
  Totals t{Vec2::Zero(), 0.0, 0.0};
  body(a, ca, t);
  body(b, cb, t);
  return t;
}

TEST_CASE("Elastic collision conserves momentum, angular momentum and energy with rotation",
          "[IM:col2D][GD:impulse][TM:NewtonThirdLawMot]") {
  // A box (56.2 kg, 74.5 kg·m²) struck off-centre by a spinning disc; contact at P = (1, 0.3).
  const Vec2 p{1.0, 0.3}, ca{1.5, 0.8}, cb{0.2, -0.1};
  CollidingBody a{1.0 / 56.2, 1.0 / 74.5, {-2.51, 0.2}, 2.1, p - ca};
  CollidingBody b{1.0 / 20.0, 1.0 / 3.0, {1.0, -0.5}, -1.0, p - cb};
  const Vec2 n = Vec2{1.0, 0.4}.normalized();
  const Totals before = totals(a, ca, b, cb);
  const auto r = gp::im::collision_response(a, b, n, 1.0);
  REQUIRE(r.impulse > 0.0);
  a.velocity = r.velocity_a;
  a.angular_velocity = r.angular_velocity_a;
  b.velocity = r.velocity_b;
  b.angular_velocity = r.angular_velocity_b;
  const Totals after = totals(a, ca, b, cb);
  CHECK_THAT((after.momentum - before.momentum).norm(), WithinAbs(0.0, 1e-13));
  CHECK_THAT(after.angular_momentum, WithinAbs(before.angular_momentum, 1e-13));
  CHECK_THAT(after.energy, WithinRel(before.energy, 1e-15));
}

TEST_CASE("Equal masses in a head-on elastic collision exchange velocities", "[IM:col2D]") {
  const CollidingBody a{1.0 / 56.2, 0.0, {-2.51, 0.0}, 0.0, {-0.5, 0.0}};
  const CollidingBody b{1.0 / 56.2, 0.0, {1.0, 0.0}, 0.0, {0.5, 0.0}};
  const auto r = gp::im::collision_response(a, b, {1.0, 0.0}, 1.0);
  CHECK_THAT((r.velocity_a - b.velocity).norm(), WithinAbs(0.0, 1e-14));
  CHECK_THAT((r.velocity_b - a.velocity).norm(), WithinAbs(0.0, 1e-14));
}

TEST_CASE("Inelastic bounce on an immovable floor keeps C_R of the normal speed",
          "[IM:col2D][via:DD:coeffRestitution]") {
  const CollidingBody ball{1.0 / 56.2, 0.0, {0.7, -2.51}, 0.0, {0.0, -0.412}};
  const CollidingBody floor{0.0, 0.0, Vec2::Zero(), 0.0, Vec2::Zero()};
  const auto r = gp::im::collision_response(ball, floor, {0.0, 1.0}, 0.8);
  CHECK_THAT(r.velocity_a.y(), WithinRel(0.8 * 2.51, 1e-15));
  CHECK(r.velocity_a.x() == 0.7);  // frictionless (A:dampingInvolvement): tangent speed kept
  CHECK(r.velocity_b.norm() == 0.0);
  CHECK_THAT(r.impulse, WithinRel(1.8 * 56.2 * 2.51, 1e-15));  // J = m Δv
}

TEST_CASE("An off-centre hit sets a resting rod spinning as the closed form predicts",
          "[IM:col2D][DD:torque]") {
  // A point mass m at speed u hits, elastically, the end of a resting rod (M, length L) at right
  // angles. Conservation of momentum, angular momentum and energy give (Hibbeler, eccentric
  // impact): j = 2 u / (1/m + 1/M + (L/2)²/I), ω = j (L/2) / I with I = M L²/12.
  const double m = 2.0, M = 56.2, L = 1.0, u = 2.51, I = M * L * L / 12.0;
  const CollidingBody rod{1.0 / M, 1.0 / I, Vec2::Zero(), 0.0, {L / 2, 0.0}};
  const CollidingBody point{1.0 / m, 0.0, {0.0, -u}, 0.0, Vec2::Zero()};
  const auto r = gp::im::collision_response(rod, point, {0.0, -1.0}, 1.0);
  const double j = 2.0 * u / (1.0 / m + 1.0 / M + (L / 2) * (L / 2) / I);
  CHECK_THAT(r.impulse, WithinRel(j, 1e-15));
  CHECK_THAT(r.angular_velocity_a, WithinRel(-j * (L / 2) / I, 1e-15));
  CHECK_THAT(r.velocity_a.y(), WithinRel(-j / M, 1e-15));
}

TEST_CASE("Separating bodies receive no impulse", "[IM:col2D]") {
  const CollidingBody a{1.0, 1.0, {0.0, 1.0}, 0.0, {0.0, -0.5}};
  const CollidingBody b{1.0, 1.0, {0.0, -1.0}, 0.0, {0.0, 0.5}};
  const auto r = gp::im::collision_response(a, b, {0.0, 1.0}, 1.0);
  CHECK(r.impulse == 0.0);
  CHECK(r.velocity_a == a.velocity);
  CHECK(r.velocity_b == b.velocity);
}

}  // namespace test_instance_models
}  // namespace
