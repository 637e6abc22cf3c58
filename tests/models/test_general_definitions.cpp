// GD checks against measured physics (surface gravity of the Earth) and against the conservation
// and restitution laws the impulse must satisfy.
// Criteria: rounding of a few operations, measured 0 to 3e-14; exact results are held to a few
// ulps (1e-15 relative), so that a change of evaluation order alone does not fail them.
#include <catch2/catch.hpp>

#include "gamephysics/models.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;

TEST_CASE("Gravitational acceleration at the Earth's surface is about 9.82 m/s² downwards",
          "[GD:accelGravity]") {
  const double G = 6.6743e-11, earth_mass = 5.9722e24, earth_radius = 6.371e6;
  const Vec2 g = gp::gd::gravitational_acceleration(G, earth_mass, Vec2{0.0, earth_radius});
  // Measured standard gravity is 9.80665 m/s² including the centrifugal term (~0.03 m/s²).
  CHECK_THAT(g.norm(), WithinAbs(9.82, 1e-3));
  CHECK(g.y() < 0.0);  // towards the centre of the Earth
  CHECK(g.x() == 0.0);
}

TEST_CASE("Gravitational field times mass equals the gravitational force",
          "[GD:accelGravity][TM:UniversalGravLaw]") {
  const double G = 6.6743e-11;
  const Vec2 from_large_to_small{3.0, -4.0};
  const Vec2 g = gp::gd::gravitational_acceleration(G, 1e10, from_large_to_small);
  const Vec2 force_on_small = gp::tm::gravitational_force(G, 56.2, 1e10, -from_large_to_small);
  CHECK_THAT((56.2 * g - force_on_small).norm(), WithinAbs(0.0, 1e-15));
}

namespace {
namespace test_general_definitions {
// Applies an impulse j n to A and −j n to B, as the impulse-momentum theorem prescribes; written
// out here rather than through IM:col2D so that GD:impulse is checked on its own.
struct Body {
  double m, I;
  Vec2 v;
  double w;
  Vec2 r;
};
Vec2 contact_velocity(const Body& b) {
  return b.v + b.w * Vec2{-b.r.y(), b.r.x()};
}
void apply(Body& b, const Vec2& impulse) {
  b.v += impulse / b.m;
  b.w += (b.r.x() * impulse.y() - b.r.y() * impulse.x()) / b.I;
}

TEST_CASE("Collision impulse of a 1D head-on collision matches the closed form", "[GD:impulse]") {
  // 1D: j = (1 + C_R) m_A m_B / (m_A + m_B) · closing speed (Hibbeler, central impact).
  const double ma = 56.2, mb = 74.5, cr = 0.8, closing = 2.51;
  const double j = gp::gd::collision_impulse(cr, Vec2{-closing, 0.0}, Vec2{1.0, 0.0}, 1.0 / ma,
                                             1.0 / mb, 0.0, 0.0, Vec2::Zero(), Vec2::Zero());
  CHECK_THAT(j, WithinRel((1.0 + cr) * ma * mb / (ma + mb) * closing, 1e-15));
}

TEST_CASE("Collision impulse with rotation obeys restitution and conserves momentum",
          "[GD:impulse][DD:coeffRestitution]") {
  const double cr = GENERATE(0.0, 0.8, 1.0);
  Body a{56.2, 74.5, {0.5, -2.51}, 2.1, {0.3, -0.4}};
  Body b{20.0, 5.0, {0.0, 1.0}, -1.0, {-0.2, 0.35}};
  const Vec2 n{0.0, 1.0};
  const Vec2 vi = contact_velocity(a) - contact_velocity(b);
  REQUIRE(vi.dot(n) < 0.0);
  const double j =
      gp::gd::collision_impulse(cr, vi, n, 1.0 / a.m, 1.0 / b.m, 1.0 / a.I, 1.0 / b.I, a.r, b.r);
  const Vec2 momentum_before = a.m * a.v + b.m * b.v;
  apply(a, j * n);
  apply(b, -j * n);
  const Vec2 vf = contact_velocity(a) - contact_velocity(b);
  CHECK_THAT(vf.dot(n), WithinAbs(-cr * vi.dot(n), 1e-13));
  CHECK_THAT(gp::dd::coefficient_of_restitution(vf, vi, n), WithinAbs(cr, 1e-13));
  CHECK_THAT((a.m * a.v + b.m * b.v - momentum_before).norm(), WithinAbs(0.0, 1e-13));
}

}  // namespace test_general_definitions
}  // namespace
