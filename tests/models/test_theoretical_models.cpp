// TM checks against hand computations from the SRS's reasonable values (srs/catalog.json,
// input_constraints) and against the physical laws themselves.
// Criteria: rounding of a few operations, measured 0 to 3e-14; exact results are held to a few
// ulps (1e-15 relative), so that a change of evaluation order alone does not fail them.
#include <catch2/catch.hpp>

#include "gamephysics/models.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;

namespace {
namespace test_theoretical_models {

TEST_CASE("Newton's second law gives a = F/m for the SRS's reasonable values",
          "[TM:NewtonSecLawMot]") {
  // Hand computation: 98.1 N / 56.2 kg = 1.745551601423488 m/s².
  const Vec2 a = gp::tm::acceleration_from_force({98.1, 0.0}, 56.2);
  CHECK_THAT(a.x(), WithinRel(1.745551601423488, 1e-15));
  CHECK(a.y() == 0.0);
  // The law as the SRS states it: m a reproduces F in every direction.
  const Vec2 force{-3.0, 4.0};
  const Vec2 a2 = gp::tm::acceleration_from_force(force, 2.5);
  CHECK_THAT((2.5 * a2 - force).norm(), WithinAbs(0.0, 1e-15));
}

TEST_CASE("Newton's third law: action and reaction cancel", "[TM:NewtonThirdLawMot]") {
  const Vec2 action{98.1, -12.5};
  const Vec2 reaction = gp::tm::reaction_force(action);
  CHECK((action + reaction).norm() == 0.0);
  CHECK(reaction.norm() == action.norm());
}

TEST_CASE("Universal gravitation: magnitude, direction, inverse square, reciprocity",
          "[TM:UniversalGravLaw]") {
  const double G = 6.6743e-11;
  // Two 56.2 kg bodies 0.412 m apart: F = G m² / d² = 1.2418923e-6 N (hand computation).
  const Vec2 d{0.412, 0.0};
  const Vec2 f = gp::tm::gravitational_force(G, 56.2, 56.2, d);
  CHECK_THAT(f.norm(), WithinRel(6.6743e-11 * 56.2 * 56.2 / (0.412 * 0.412), 1e-15));
  CHECK_THAT(f.norm(), WithinRel(1.24189227e-6, 1e-8));
  CHECK(f.x() > 0.0);  // body 1 is pulled towards body 2
  // Inverse square: twice the distance, a quarter of the force.
  CHECK_THAT(gp::tm::gravitational_force(G, 56.2, 56.2, 2.0 * d).norm(),
             WithinRel(f.norm() / 4.0, 1e-15));
  // Reciprocity (TM:NewtonThirdLawMot): the force on body 2 is the reaction.
  const Vec2 on_2 = gp::tm::gravitational_force(G, 56.2, 74.5, Vec2{-0.3, -0.4});
  const Vec2 on_1 = gp::tm::gravitational_force(G, 74.5, 56.2, Vec2{0.3, 0.4});
  CHECK_THAT((on_1 + on_2).norm(), WithinAbs(0.0, 1e-15 * on_1.norm()));
}

TEST_CASE("Newton's second law for rotation gives α = τ/I for the SRS's reasonable values",
          "[TM:NewtonSecLawRotMot]") {
  // Hand computation: 200 N·m / 74.5 kg·m² = 2.684563758389262 rad/s².
  CHECK_THAT(gp::tm::angular_acceleration_from_torque(200.0, 74.5),
             WithinRel(2.684563758389262, 1e-15));
  CHECK(gp::tm::angular_acceleration_from_torque(-200.0, 74.5) < 0.0);
}

}  // namespace test_theoretical_models
}  // namespace
