// A scene file's fields reach the engine as given, and what the file leaves out takes the
// documented default (FR:Input-Initial-Conditions, FR:Input-Surface-Properties).
#include <catch2/catch.hpp>
#include <variant>

#include "engine/scene/scene_space.hpp"
#include "scene_files.hpp"

using gp::test::load;
using gp::test::scene_with;

namespace {
namespace test_scene_loading {

TEST_CASE("Settings and time stepping are read from the file", "[FR:Input-Initial-Conditions]") {
  const gp::Scene scene = load(R"({"gravity": [0.5, -9.81], "G": 6.674e-11,
      "integrator": "rk4", "dt": 0.002, "duration": 3, "output_dt": 0.1,
      "velocity_iterations": 7, "velocity_tolerance": 1e-3, "direct_solve_points": 12,
      "direct_solve_uneven_points": 300, "direct_solve_mass_ratio": 4.5,
      "direct_solve_resting_points": 900, "position_iterations": 2,
      "restitution_threshold": 0.5,
      "description": "all the settings", "bodies": []})");
  CHECK(scene.settings.gravity == gp::Vec2(0.5, -9.81));
  CHECK(scene.settings.G == 6.674e-11);
  CHECK(scene.settings.integrator == gp::IntegratorKind::RK4);
  CHECK(scene.settings.velocity_iterations == 7);
  CHECK(scene.settings.velocity_tolerance == 1e-3);
  CHECK(scene.settings.direct_solve_points == 12);
  CHECK(scene.settings.direct_solve_uneven_points == 300);
  CHECK(scene.settings.direct_solve_mass_ratio == 4.5);
  CHECK(scene.settings.direct_solve_resting_points == 900);
  CHECK(scene.settings.position_iterations == 2);
  CHECK(scene.settings.restitution_threshold == 0.5);
  CHECK(scene.dt == 0.002);
  CHECK(scene.duration == 3.0);
  CHECK(scene.output_dt == 0.1);
  CHECK(scene.bodies.empty());
}

TEST_CASE("Settings left out take the engine's defaults, and output_dt defaults to dt",
          "[FR:Input-Initial-Conditions]") {
  const gp::Scene scene = load(scene_with(""));
  const gp::Settings defaults;
  CHECK(scene.settings.gravity == gp::Vec2::Zero());
  CHECK_FALSE(scene.settings.G.has_value());
  CHECK(scene.settings.integrator == gp::IntegratorKind::VelocityVerlet);
  CHECK(scene.settings.velocity_iterations == defaults.velocity_iterations);
  CHECK(scene.settings.velocity_tolerance == defaults.velocity_tolerance);
  CHECK(scene.settings.direct_solve_points == defaults.direct_solve_points);
  CHECK(scene.settings.direct_solve_uneven_points == defaults.direct_solve_uneven_points);
  CHECK(scene.settings.direct_solve_mass_ratio == defaults.direct_solve_mass_ratio);
  CHECK(scene.settings.direct_solve_resting_points == defaults.direct_solve_resting_points);
  CHECK(scene.settings.position_iterations == defaults.position_iterations);
  CHECK(scene.settings.restitution_threshold == defaults.restitution_threshold);
  CHECK(scene.output_dt == scene.dt);
}

TEST_CASE("Overrides replace the file's values and may supply missing ones",
          "[FR:Input-Initial-Conditions]") {
  gp::SceneOverrides overrides;
  overrides.integrator = "symplectic_euler";
  overrides.dt = 0.5;
  overrides.duration = 4.0;
  overrides.output_dt = 1.0;
  const gp::Scene scene = load(R"({"integrator": "rk4", "bodies": []})", overrides);
  CHECK(scene.settings.integrator == gp::IntegratorKind::SymplecticEuler);
  CHECK(scene.dt == 0.5);
  CHECK(scene.duration == 4.0);
  CHECK(scene.output_dt == 1.0);
}

TEST_CASE("Every initial condition of a body is read", "[FR:Input-Initial-Conditions]") {
  const gp::Scene scene = load(scene_with(R"({"name": "rock", "type": "dynamic",
      "position": [1, 2], "angle": 0.5, "velocity": [3, -4], "angular_velocity": 2.1,
      "mass": 56.2, "moment": 74.5, "force": [98.1, 0], "force_point": [0, 0.25],
      "torque": 200})"));
  REQUIRE(scene.bodies.size() == 1);
  const gp::BodyDef& body = scene.bodies[0];
  CHECK(body.name == "rock");
  CHECK(body.type == gp::BodyType::Dynamic);
  CHECK(body.position == gp::Vec2(1, 2));
  CHECK(body.angle == 0.5);
  CHECK(body.velocity == gp::Vec2(3, -4));
  CHECK(body.angular_velocity == 2.1);
  CHECK(body.mass == 56.2);
  CHECK(body.moment == 74.5);
  CHECK(body.force == gp::Vec2(98.1, 0));
  CHECK(body.force_point == gp::Vec2(0, 0.25));
  CHECK(body.torque == 200.0);
  CHECK(body.shapes.empty());
}

TEST_CASE("A body's optional fields take the BodyDef defaults", "[FR:Input-Initial-Conditions]") {
  const gp::Scene scene = load(scene_with(R"({"name": "p", "position": [0, 0], "mass": 1},
      {"name": "wall", "type": "static", "position": [0, 0],
       "shapes": [{"type": "box", "width": 1, "height": 2}]},
      {"name": "lift", "type": "kinematic", "position": [0, 0], "velocity": [0, 1],
       "shapes": [{"type": "box", "width": 1, "height": 2}]})"));
  REQUIRE(scene.bodies.size() == 3);
  const gp::BodyDef defaults;
  const gp::BodyDef& p = scene.bodies[0];
  CHECK(p.type == gp::BodyType::Dynamic);
  CHECK(p.angle == defaults.angle);
  CHECK(p.velocity == defaults.velocity);
  CHECK(p.angular_velocity == defaults.angular_velocity);
  CHECK_FALSE(p.moment.has_value());
  CHECK(p.force == defaults.force);
  CHECK_FALSE(p.force_point.has_value());
  CHECK(p.torque == defaults.torque);
  CHECK(scene.bodies[1].type == gp::BodyType::Static);
  CHECK(scene.bodies[2].type == gp::BodyType::Kinematic);
  CHECK(scene.bodies[2].velocity == gp::Vec2(0, 1));
}

TEST_CASE("Every shape type is read with its geometry", "[FR:Input-Initial-Conditions]") {
  const gp::Scene scene = load(scene_with(R"({"name": "b", "position": [0, 0], "shapes": [
      {"type": "circle", "radius": 0.5, "center": [1, 2]},
      {"type": "box", "width": 2, "height": 4, "center": [0, -1]},
      {"type": "polygon", "vertices": [[0, 0], [0, 1], [1, 0]]},
      {"type": "segment", "a": [-10, 0], "b": [10, 0], "radius": 0.1}]})"));
  const auto& shapes = scene.bodies.at(0).shapes;
  REQUIRE(shapes.size() == 4);
  const auto& circle = std::get<gp::Circle>(shapes[0].shape.geometry());
  CHECK(circle.radius == 0.5);
  CHECK(circle.center == gp::Vec2(1, 2));
  const auto& box = std::get<gp::ConvexPolygon>(shapes[1].shape.geometry());
  REQUIRE(box.count == 4);
  for (int i = 0; i < 4; ++i) {
    CHECK(std::abs(box.vertices[i].x()) == 1.0);
    CHECK((box.vertices[i].y() == 1.0 || box.vertices[i].y() == -3.0));
  }
  // Given clockwise; the factory turns it counter-clockwise.
  const auto& triangle = std::get<gp::ConvexPolygon>(shapes[2].shape.geometry());
  CHECK(triangle.count == 3);
  const auto& segment = std::get<gp::Segment>(shapes[3].shape.geometry());
  CHECK(segment.a == gp::Vec2(-10, 0));
  CHECK(segment.b == gp::Vec2(10, 0));
  CHECK(segment.radius == 0.1);
}

TEST_CASE("Surface properties and densities are read per shape, defaults from ShapeDef",
          "[FR:Input-Surface-Properties]") {
  const gp::Scene scene = load(scene_with(R"({"name": "b", "position": [0, 0], "shapes": [
      {"type": "circle", "radius": 0.5, "restitution": 0.8, "friction": 0.6, "density": 2.5},
      {"type": "segment", "a": [0, 0], "b": [1, 0]}]})"));
  const auto& shapes = scene.bodies.at(0).shapes;
  REQUIRE(shapes.size() == 2);
  CHECK(shapes[0].restitution == 0.8);
  CHECK(shapes[0].friction == 0.6);
  CHECK(shapes[0].density == 2.5);
  const gp::ShapeDef defaults{gp::Shape::circle(1.0)};
  CHECK(shapes[1].restitution == defaults.restitution);
  CHECK(shapes[1].friction == defaults.friction);
  CHECK(shapes[1].density == defaults.density);
}

TEST_CASE("The space has the scene's bodies in file order", "[FR:Input-Initial-Conditions]") {
  const gp::Scene scene = load(R"({"gravity": [0, -9.81], "dt": 0.01, "duration": 1, "bodies": [
      {"name": "ground", "type": "static", "position": [0, 0],
       "shapes": [{"type": "segment", "a": [-10, 0], "b": [10, 0]}]},
      {"name": "ball", "position": [0, 10], "velocity": [1, 0],
       "shapes": [{"type": "circle", "radius": 0.5, "center": [1, 0], "density": 2}]}]})");
  const auto space = gp::build_space(scene);
  REQUIRE(space->body_count() == 2);
  CHECK(space->name(0) == "ground");
  CHECK(space->name(1) == "ball");
  CHECK(space->settings().gravity == gp::Vec2(0, -9.81));
  // The body frame's origin is `position`; the engine reports the centre of mass.
  CHECK(space->state(1).position == gp::Vec2(1, 10));
  CHECK(space->state(1).velocity == gp::Vec2(1, 0));
  CHECK(space->mass(1) == Approx(2 * 3.141592653589793 * 0.25));
}

}  // namespace test_scene_loading
}  // namespace
