// The optional Box2D 3 peer (built only with GP_BOX2D3_DIR): what it is given, read back through
// Box2D 3's own API, and how it moves bodies, against its own closed form.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "engine/geometry/transform.hpp"
#include "peer_scenes.hpp"
#include "verification/bench/bench_engine.hpp"
#include "verification/peers/box2d3/box2d3_world.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;
using gp::peers::Box2d3World;
using gp::peers::PeerConfig;
using gp::peers::PeerEngine;
using gp::peers::testing::empty_scene;

namespace {
namespace test_box2d3_peer {

TEST_CASE("Box2D 3 moves a projectile as sub-stepped symplectic Euler to float precision",
          "[NFR:Correctness][peers]") {
  // Each of its 4 sub-steps of s = h/4 updates the velocity, then moves with it: after N = 4n
  // sub-steps x_N = x₀ + v₀ N s + g s² N(N + 1)/2, v_N = v₀ + g N s.
  using gp::peers::testing::projectile::g;
  using gp::peers::testing::projectile::h;
  using gp::peers::testing::projectile::steps;
  using gp::peers::testing::projectile::v0;
  using gp::peers::testing::projectile::x0;
  const auto world = gp::peers::testing::thrown_projectile(PeerEngine::Box2d3);
  const gp::BodyState state = world->state(0);
  const double s = h / Box2d3World::kSubSteps;
  const double N = steps * Box2d3World::kSubSteps;
  const Vec2 x = x0 + v0 * N * s + g * s * s * N * (N + 1) / 2;
  const Vec2 v = v0 + g * N * s;
  // Single precision, criteria 4 to 10 times the error measured: x 4.6e-5 m (24 float ulps at
  // 21.5 m, from adding each step's move to the position), y 5.9e-6 m, v_y 1.1e-6 m/s.
  CHECK_THAT(state.position.x(), WithinAbs(x.x(), 2e-4));
  CHECK_THAT(state.position.y(), WithinAbs(x.y(), 3e-5));
  CHECK_THAT(state.velocity.y(), WithinAbs(v.y(), 1e-5));
  CHECK(state.velocity.x() == v0.x());
  // Whole steps without sub-steps would end 1.5 g s² N = 0.074 m lower: the test tells them apart.
  CHECK(std::abs(state.position.y() - (x.y() + 1.5 * g.y() * s * s * N)) > 0.05);
}

// A right triangle (legs 3 m and 1.5 m, centroid (1, 0.5) off the body origin), density
// 2 kg/m², at (1, 2) turned by 0.3 rad: m = 4.5 kg, I = m (a² + b²) / 18 = 2.8125 kg·m².
TEST_CASE("Box2D 3 gets our mass, moment, centre of mass and polygon without skin",
          "[NFR:Correctness][peers]") {
  const std::array<Vec2, 3> triangle{Vec2{0.0, 0.0}, Vec2{3.0, 0.0}, Vec2{0.0, 1.5}};
  const gp::Transform placement({1.0, 2.0}, 0.3);
  gp::Scene scene = empty_scene(1.0 / 60.0);
  gp::BodyDef body;
  body.name = "triangle";
  body.position = placement.position();
  body.angle = placement.angle();
  body.shapes.push_back({gp::Shape::polygon(triangle), 0.0, 0.0, 2.0});
  scene.bodies.push_back(body);
  const Box2d3World world(gp::peers::peer_scene(scene));
  const gp::peers::Box2d3Body read = world.body(0);
  CHECK_THAT(read.mass, WithinRel(4.5, 1e-6));
  CHECK_THAT(read.moment, WithinRel(4.5 * (9.0 + 2.25) / 18.0, 1e-6));
  CHECK(read.local_center == Vec2::Zero());
  const Vec2 center = placement.apply({1.0, 0.5});
  CHECK_THAT(read.origin.x(), WithinAbs(center.x(), 1e-6));
  CHECK_THAT(read.origin.y(), WithinAbs(center.y(), 1e-6));
  CHECK_THAT(world.state(0).angle, WithinAbs(0.3, 1e-7));
  // Our vertices, in whatever order Box2D 3's hull starts from, with no rounding.
  CHECK(read.polygon_radius == 0.0);
  REQUIRE(read.polygon_vertices.size() == 3);
  for (const Vec2& corner : triangle) {
    const Vec2 expected = placement.apply(corner);
    const bool found = std::any_of(read.polygon_vertices.begin(), read.polygon_vertices.end(),
                                   [&](const Vec2& w) { return (w - expected).norm() < 1e-6; });
    INFO(expected.transpose());
    CHECK(found);
  }
}

gp::BodyDef static_segment(const Vec2& a, const Vec2& b) {
  gp::BodyDef def;
  def.name = "segment";
  def.type = gp::BodyType::Static;
  def.shapes.push_back({gp::Shape::segment(a, b, 0.0), 0.0, 0.6});
  return def;
}

TEST_CASE("Box2D 3 holds a box on a box floor and a disc on a segment within millimetres",
          "[NFR:Correctness][peers]") {
  gp::Scene scene = empty_scene(1.0 / 60.0);
  scene.settings.gravity = {0.0, -9.81};
  scene.duration = 2.0;
  scene.bodies.push_back(gp::peers::testing::floor_box(20.0, 0.6));
  scene.bodies.push_back(gp::peers::testing::box_body("box", 1.0, 1.0, {-3.0, 0.5}, 0.6));
  scene.bodies.push_back(static_segment({20.0, 0.0}, {30.0, 0.0}));
  scene.bodies.push_back(gp::peers::testing::ball("disc", {25.0, 0.5}, Vec2::Zero(), 1.0, 0.0));
  for (const PeerConfig config : {PeerConfig::Default, PeerConfig::Matched}) {
    auto world = gp::peers::make_peer(PeerEngine::Box2d3, gp::peers::peer_scene(scene, config));
    for (int n = 0; n < 120; ++n) world->step(scene.dt);
    INFO(gp::peers::config_name(config));
    // Soft contacts leave an overlap under the weight (measured 0.09 mm under the box, 0.07 mm
    // under the disc, drift 1e-5 m, angle 8e-8 rad): criteria about 10 times these.
    for (const gp::BodyId id : {gp::BodyId{1}, gp::BodyId{3}}) {
      const gp::BodyState s = world->state(id);
      INFO(world->name(id));
      CHECK_THAT(s.position.y(), WithinAbs(0.5, 1e-3));
      CHECK_THAT(s.position.x(), WithinAbs(scene.bodies[id].position.x(), 1e-4));
      CHECK(s.velocity.norm() < 1e-4);
    }
    const double angle = world->state(1).angle;
    CHECK(std::min(angle, 2 * std::numbers::pi - angle) < 1e-6);
  }
}

TEST_CASE("Box2D 3 bounces with the larger restitution of the two surfaces",
          "[NFR:Correctness][peers]") {
  // A disc of C_R = 0.5 falls 1 m onto a floor of C_R = 0: it hits at √(2 g) = 4.43 m/s, above
  // either restitution threshold, and leaves at max(0.5, 0) times that (a product would be 0).
  gp::Scene scene = empty_scene(1.0 / 240.0);
  scene.settings.gravity = {0.0, -9.81};
  scene.bodies.push_back(gp::peers::testing::floor_box(20.0, 0.0));
  scene.bodies.push_back(gp::peers::testing::ball("disc", {0.0, 1.5}, Vec2::Zero(), 1.0, 0.5));
  for (const PeerConfig config : {PeerConfig::Default, PeerConfig::Matched}) {
    auto world = gp::peers::make_peer(PeerEngine::Box2d3, gp::peers::peer_scene(scene, config));
    double fastest_up = 0.0;
    for (int n = 0; n < 240; ++n) {
      world->step(scene.dt);
      fastest_up = std::max(fastest_up, world->state(1).velocity.y());
    }
    INFO(gp::peers::config_name(config));
    // Measured 0.6% faster (the discrete fall): criterion 5 times that.
    CHECK_THAT(fastest_up, WithinRel(0.5 * std::sqrt(2 * 9.81), 0.03));
  }
}

TEST_CASE("Box2D 3 is the peer box2d3, on the bench as box2d3-default and box2d3-matched",
          "[NFR:Correctness][peers]") {
  CHECK(gp::peers::engine_from_name("box2d3") == PeerEngine::Box2d3);
  CHECK(gp::peers::engine_name(PeerEngine::Box2d3) == "box2d3");
  CHECK(gp::peers::engine_choices() == "chipmunk, box2d or box2d3");
  CHECK_THAT(std::string(gp::peers::library_build(PeerEngine::Box2d3)),
             Contains("float, Box2D 3.") && Contains("built from GP_BOX2D3_DIR") &&
                 Contains("4 sub-steps"));
  CHECK(gp::bench::engine_label(gp::bench::Engine::Box2d3Default) == "box2d3-default");
  CHECK(gp::bench::engine_label(gp::bench::Engine::Box2d3Matched) == "box2d3-matched");
  gp::Scene scene = empty_scene(0.01);
  scene.settings.restitution_threshold = 0.05;
  const auto as_is = gp::peers::peer_scene(scene, PeerConfig::Default);
  const auto matched = gp::peers::peer_scene(scene, PeerConfig::Matched);
  CHECK_THAT(Box2d3World(as_is).describe(),
             Contains("Box2D 3.") && Contains("restitution threshold 1 m/s, sleeping on"));
  CHECK_THAT(Box2d3World(matched).describe(),
             Contains("restitution threshold 0.05 m/s, sleeping off"));
}

}  // namespace test_box2d3_peer
}  // namespace
