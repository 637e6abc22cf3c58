// Surface properties (FR:Input-Surface-Properties): friction decelerates a sliding box at μ g
// (LC:Include-Dampening), and contacts combine C_R = max(a, b) and μ = √(μa μb).
// Criteria of the closed-form checks: 3 to 10 times the error measured (Release), and no tighter
// than rounding, 1e-15 of the value (at least 1e-15), where the engine meets the closed form
// exactly.
#include <catch2/catch.hpp>
#include <cmath>

#include "gamephysics/gamephysics.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
namespace test_space_surfaces {
constexpr double g = 9.81;

gp::Settings with_gravity() {
  gp::Settings settings;
  settings.gravity = {0.0, -g};
  return settings;
}

// A unit box resting on a wide static ground box and moving at v0 along it; returns the box.
gp::BodyId add_box_on_ground(gp::Space& space, double friction_box, double friction_ground,
                             double v0) {
  gp::BodyDef ground;
  ground.name = "ground";
  ground.type = gp::BodyType::Static;
  ground.position = {0.0, -0.5};
  ground.shapes.push_back({gp::Shape::box(100.0, 1.0), 0.0, friction_ground});
  space.add_body(ground);
  gp::BodyDef box;
  box.name = "box";
  box.position = {0.0, 0.5};
  box.velocity = {v0, 0.0};
  box.shapes.push_back({gp::Shape::box(1.0, 1.0), 0.0, friction_box});
  return space.add_body(box);
}

// The distance the box of add_box_on_ground slides before stopping.
double sliding_distance(double friction_box, double friction_ground, double v0) {
  gp::Space space(with_gravity());
  const auto id = add_box_on_ground(space, friction_box, friction_ground, v0);
  for (int k = 0; k < 240; ++k) space.step(1.0 / 120);
  CHECK_THAT(space.state(id).velocity.norm(), WithinAbs(0.0, 1e-15));  // it has stopped
  CHECK_THAT(space.state(id).position.y(), WithinAbs(0.5, 1e-15));     // and stayed on top
  return space.state(id).position.x();
}

TEST_CASE("Friction stops a sliding box after v₀² / (2 μ g)",
          "[FR:Input-Surface-Properties][FR:Determine-Collision-Response-Over-Time]") {
  // Coulomb friction decelerates at μ g: the box slides v₀² / (2 μ g) = 0.9174 m for μ = 0.5.
  CHECK_THAT(sliding_distance(0.5, 0.5, 3.0), WithinRel(9.0 / (2 * 0.5 * g), 2e-4));
  // μ = √(0.2 · 0.8) = 0.4 when the two surfaces differ.
  CHECK_THAT(sliding_distance(0.2, 0.8, 3.0), WithinRel(9.0 / (2 * 0.4 * g), 1e-4));
}

TEST_CASE("A frictionless box keeps sliding",
          "[FR:Input-Surface-Properties][A:dampingInvolvement]") {
  gp::Space space(with_gravity());
  const auto id = add_box_on_ground(space, 0.0, 0.8, 3.0);  // μ = √(0 · 0.8) = 0
  for (int k = 0; k < 120; ++k) space.step(1.0 / 60);
  CHECK_THAT(space.state(id).velocity.x(), WithinAbs(3.0, 5e-15));
  CHECK_THAT(space.state(id).position.x(), WithinAbs(6.0, 5e-14));
}

TEST_CASE("The bouncier surface sets the restitution of a contact",
          "[FR:Input-Surface-Properties]") {
  gp::Space space(with_gravity());
  gp::BodyDef ground;
  ground.name = "ground";
  ground.type = gp::BodyType::Static;
  ground.shapes.push_back({gp::Shape::segment({-5, 0}, {5, 0}), 0.9});
  space.add_body(ground);
  gp::BodyDef ball;
  ball.name = "ball";
  ball.position = {0.0, 5.5};
  ball.shapes.push_back({gp::Shape::circle(0.5), 0.2});
  const auto id = space.add_body(ball);
  while (space.impacts().empty()) space.step(1.0 / 60);
  // Just after the impact the ball leaves at C_R = max(0.2, 0.9) times its arrival speed √(2 g h).
  const double arrival = std::sqrt(2 * g * 5.0);
  const double t_after = space.time() - space.impacts()[0].time;
  CHECK_THAT(space.state(id).velocity.y(), WithinAbs(0.9 * arrival - g * t_after, 2e-14));
}

}  // namespace test_space_surfaces
}  // namespace
