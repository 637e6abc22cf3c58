// A step runs only what the scene needs, and says so with SRS ids; runs are deterministic.
#include <algorithm>
#include <catch2/catch.hpp>

#include "gamephysics/gamephysics.hpp"

namespace {
namespace test_space_pipeline {
// The stage whose name starts with `name`, among those the space needs; nullptr if none.
const gp::PipelineStage* needed(const std::vector<gp::PipelineStage>& stages,
                                const std::string& name) {
  const auto it = std::find_if(stages.begin(), stages.end(), [&](const gp::PipelineStage& s) {
    return s.needed && s.name.rfind(name, 0) == 0;
  });
  return it == stages.end() ? nullptr : &*it;
}
bool has(const std::vector<gp::PipelineStage>& stages, const std::string& name) {
  return needed(stages, name) != nullptr;
}
bool mentions(const std::vector<gp::PipelineStage>& stages, const std::string& name,
              const std::string& text) {
  const gp::PipelineStage* s = needed(stages, name);
  return s && s->description.find(text) != std::string::npos;
}
gp::BodyDef disc(const std::string& name, const gp::Vec2& position) {
  gp::BodyDef def;
  def.name = name;
  def.position = position;
  def.shapes.push_back({gp::Shape::circle(0.5), 0.5});
  return def;
}

TEST_CASE("A free point mass under gravity runs no collision or rotation stage",
          "[FR:Simulation-Space]") {
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  gp::BodyDef point;
  point.name = "p";
  point.mass = 1.0;
  space.add_body(point);
  const auto stages = space.pipeline();
  CHECK(mentions(stages, "integration", "uniform gravity"));
  CHECK(mentions(stages, "integration", "0 of them rotating"));
  CHECK_FALSE(mentions(stages, "integration", "pairwise gravitation"));
  CHECK_FALSE(has(stages, "broadphase"));
  CHECK_FALSE(has(stages, "narrowphase"));
}

TEST_CASE("Shapes collide only once two bodies have shapes and one of them is dynamic",
          "[FR:Determine-Collisions]") {
  gp::Space space(gp::Settings{});
  const auto wall = [](const std::string& name, double y) {
    gp::BodyDef def;
    def.name = name;
    def.type = gp::BodyType::Static;
    def.shapes.push_back({gp::Shape::segment({-5, y}, {5, y})});
    return def;
  };
  space.add_body(wall("floor", -5));
  space.add_body(wall("ceiling", 5));
  gp::BodyDef point;
  point.name = "p";
  point.mass = 1.0;
  space.add_body(point);
  // Two static walls and a dynamic body without a shape: nothing can touch.
  CHECK_FALSE(has(space.pipeline(), "broadphase"));
  space.add_body(disc("a", {0, 0}));
  CHECK(has(space.pipeline(), "broadphase"));
}

TEST_CASE("Colliding discs and G bring in their stages with their SRS ids",
          "[FR:Simulation-Space][FR:Determine-Collisions]") {
  gp::Settings settings;
  settings.G = 6.6743e-11;
  gp::Space space(settings);
  space.add_body(disc("a", {0, 0}));
  space.add_body(disc("b", {3, 0}));
  gp::BodyDef wall;
  wall.name = "wall";
  wall.type = gp::BodyType::Static;
  wall.shapes.push_back({gp::Shape::segment({-5, -5}, {5, -5})});
  space.add_body(wall);
  const auto stages = space.pipeline();
  CHECK(mentions(stages, "integration",
                 "pairwise gravitation G m / d², O(N²) (TM:UniversalGravLaw GD:accelGravity)"));
  CHECK(mentions(stages, "integration", "2 of them rotating"));
  CHECK(has(stages, "broadphase"));
  CHECK(has(stages, "time of impact"));
  CHECK(has(stages, "contact solver: islands solved directly"));
  // Turned off, the direct solve is not run and not listed.
  settings.direct_solve_points = 0;
  gp::Space sequential(settings);
  sequential.add_body(disc("a", {0, 0}));
  sequential.add_body(disc("b", {3, 0}));
  CHECK_FALSE(has(sequential.pipeline(), "contact solver: small islands"));
  CHECK(has(sequential.pipeline(), "contact solver: sequential impulses"));
}

TEST_CASE("The same scene gives bit-identical states every run", "[FR:Simulation-Space]") {
  const auto run = [] {
    gp::Settings settings;
    settings.gravity = {0.0, -9.81};
    gp::Space space(settings);
    // The letter inserted, not "d" + …, which GCC 12 flags falsely (-Wstringop-overflow).
    for (int i = 0; i < 30; ++i) {
      space.add_body(disc(std::to_string(i).insert(0, 1, 'd'), {0.3 * i, 1.2 * i}));
    }
    gp::BodyDef floor;
    floor.name = "floor";
    floor.type = gp::BodyType::Static;
    floor.shapes.push_back({gp::Shape::segment({-20, -1}, {20, -1})});
    space.add_body(floor);
    for (int k = 0; k < 200; ++k) space.step(1.0 / 60);
    std::vector<double> out;
    for (gp::BodyId id = 0; id < space.body_count(); ++id) {
      const auto s = space.state(id);
      out.insert(out.end(), {s.position.x(), s.position.y(), s.angle, s.velocity.x(),
                             s.velocity.y(), s.angular_velocity});
    }
    return out;
  };
  CHECK(run() == run());
}

}  // namespace test_space_pipeline
}  // namespace
