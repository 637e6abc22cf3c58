// The scenes shipped in scenes/ load, and the small ones do what their descriptions say.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>

#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene/scene.hpp"

namespace {
namespace test_shipped_scenes {

const std::filesystem::path kScenes = std::filesystem::path(GP_SOURCE_DIR) / "scenes";

struct Run {
  gp::Scene scene;
  std::unique_ptr<gp::Space> space;
};

/// The shipped scene `name`, run to its end (or to `overrides.duration`).
Run run(const std::string& name, const gp::SceneOverrides& overrides = {}) {
  Run result{gp::load_scene(kScenes / (name + ".json"), overrides), nullptr};
  result.space = gp::build_space(result.scene);
  gp::run_scene(*result.space, result.scene, [](double) {});
  return result;
}

TEST_CASE("Every shipped scene loads and builds", "[FR:Input-Initial-Conditions]") {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path());
    names.insert(entry.path().stem().string());
    const gp::Scene scene = gp::load_scene(entry.path());
    const auto space = gp::build_space(scene);
    CHECK(space->body_count() == scene.bodies.size());
    CHECK(space->body_count() > 0);
  }
  CHECK(names == std::set<std::string>{"bouncing_ball", "box_drop", "disc_roll", "head_on",
                                       "heavy_stack", "newtons_cradle", "oblique", "orbit",
                                       "projectile", "pyramid20", "pyramid6", "rain1000",
                                       "ramp_slide", "settle50", "spinning_box", "stack3",
                                       "static_friction", "step_tip"});
}

TEST_CASE("The large shipped scenes have the bodies they promise",
          "[FR:Input-Initial-Conditions][FR:Input-Surface-Properties]") {
  const gp::Scene pyramid = gp::load_scene(kScenes / "pyramid20.json");
  REQUIRE(pyramid.bodies.size() == 1 + 210);
  CHECK(pyramid.bodies[0].type == gp::BodyType::Static);
  const gp::Scene rain = gp::load_scene(kScenes / "rain1000.json");
  REQUIRE(rain.bodies.size() == 1 + 1000);
  CHECK(rain.bodies[0].shapes.size() == 3);
  for (const auto* scene : {&pyramid, &rain}) {
    for (const gp::BodyDef& body : scene->bodies) {
      for (const gp::ShapeDef& shape : body.shapes) CHECK(shape.friction == 0.6);
    }
  }
}

TEST_CASE("projectile.json flies the parabola", "[FR:Calculate-Translation-Over-Time]") {
  const auto [scene, space] = run("projectile");
  const double t = scene.duration;
  CHECK(space->state(0).position.x() == Approx(10 * t).margin(1e-9));
  CHECK(space->state(0).position.y() == Approx(10 * t - 0.5 * 9.81 * t * t).margin(1e-9));
}

TEST_CASE("spinning_box.json spins up at 3 rad/s^2", "[FR:Calculate-Rotation-Over-Time]") {
  const auto [scene, space] = run("spinning_box");
  const double t = scene.duration;
  CHECK(space->state(0).angular_velocity == Approx(3 * t).margin(1e-9));
  CHECK(space->state(0).angle == Approx(std::fmod(1.5 * t * t, 2 * std::numbers::pi)).margin(1e-9));
}

TEST_CASE("bouncing_ball.json rebounds to 0.64 of its drop", "[FR:Determine-Collisions]") {
  // Dropped from 10 m, the ball's centre falls 9.5 m to contact and rises 0.8² × 9.5 m back.
  gp::SceneOverrides first_bounce;
  first_bounce.duration = 3.5;
  const gp::Scene scene = gp::load_scene(kScenes / "bouncing_ball.json", first_bounce);
  const auto space = gp::build_space(scene);
  double apex = 0.0;
  gp::run_scene(*space, scene, [&](double t) {
    if (t > 2.0) apex = std::max(apex, space->state(1).position.y());
  });
  CHECK(apex == Approx(0.5 + 0.64 * 9.5).margin(0.01));
}

TEST_CASE("head_on.json ends with the elastic velocities",
          "[FR:Determine-Collision-Response-Over-Time]") {
  const auto [scene, space] = run("head_on");
  CHECK(space->state(0).velocity.x() == Approx(-10.0 / 3.0).margin(1e-9));
  CHECK(space->state(1).velocity.x() == Approx(2.0 / 3.0).margin(1e-9));
}

TEST_CASE("oblique.json ends with perpendicular velocities",
          "[FR:Determine-Collision-Response-Over-Time]") {
  const auto [scene, space] = run("oblique");
  const gp::Vec2 a = space->state(0).velocity;
  const gp::Vec2 b = space->state(1).velocity;
  CHECK(a.dot(b) == Approx(0).margin(1e-9));
  CHECK(a.norm() == Approx(1.0).margin(1e-9));
  CHECK(b.norm() == Approx(std::sqrt(3.0)).margin(1e-9));
  CHECK((a + b - gp::Vec2(2, 0)).norm() == Approx(0).margin(1e-9));
}

TEST_CASE("newtons_cradle.json passes the motion to the last ball",
          "[FR:Determine-Collision-Response-Over-Time]") {
  const auto [scene, space] = run("newtons_cradle");
  for (gp::BodyId ball = 0; ball < 4; ++ball) {
    CHECK(space->state(ball).velocity.norm() == Approx(0).margin(1e-9));
  }
  CHECK(space->state(4).velocity.x() == Approx(1.0).margin(1e-9));
}

TEST_CASE("orbit.json closes its circular orbit after one period",
          "[FR:Calculate-Translation-Over-Time]") {
  // Omega = sqrt(G (m1 + m2) / d^3) for d = 2 m: the period docs/scene-format.md derives.
  const double period = 2 * std::numbers::pi / std::sqrt(6.674e-11 * 4e11 / 8.0);
  gp::SceneOverrides one_period;
  one_period.duration = period;
  const gp::Scene scene = gp::load_scene(kScenes / "orbit.json", one_period);
  const auto space = gp::build_space(scene);
  gp::run_scene(*space, scene, [&](double) {
    const gp::Vec2 heavy = space->state(0).position;
    const gp::Vec2 light = space->state(1).position;
    CHECK((light - heavy).norm() == Approx(2.0).margin(1e-6));
    CHECK((3 * heavy + light).norm() == Approx(0).margin(1e-9));  // centre of mass
  });
  // Back where it started, but for the integrator's phase error (about 1e-5 m at dt = 1 ms).
  CHECK((space->state(0).position - gp::Vec2(-0.5, 0)).norm() == Approx(0).margin(1e-4));
  CHECK((space->state(1).position - gp::Vec2(1.5, 0)).norm() == Approx(0).margin(1e-4));
}

TEST_CASE("pyramid20.json stands", "[FR:Determine-Collision-Response-Over-Time]") {
  const gp::Scene scene = gp::load_scene(kScenes / "pyramid20.json");
  const auto space = gp::build_space(scene);
  std::vector<gp::Vec2> start;
  for (gp::BodyId box = 0; box < space->body_count(); ++box) {
    start.push_back(space->state(box).position);
  }
  gp::run_scene(*space, scene, [](double) {});
  for (gp::BodyId box = 1; box < space->body_count(); ++box) {
    INFO(space->name(box));
    CHECK((space->state(box).position - start[box]).norm() < 0.05);
  }
}

}  // namespace test_shipped_scenes
}  // namespace
