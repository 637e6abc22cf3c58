// Collisions in the peer engines, with our engine's rule for combining two surfaces.
#include <catch2/catch.hpp>

#include "peer_scenes.hpp"
#include "verification/peers/peer_world.hpp"

using Catch::Matchers::WithinAbs;
using gp::peers::PeerEngine;
using gp::peers::testing::ball;
using gp::peers::testing::box_body;
using gp::peers::testing::empty_scene;
using gp::peers::testing::floor_box;

namespace {
namespace test_peer_collisions {

TEST_CASE("A head-on elastic collision of equal masses exchanges velocities in both peers",
          "[NFR:Correctness][peers]") {
  // One surface is elastic, the other not: our rule takes the larger C_R (1), where Chipmunk's
  // own product would take 0 and stop both balls.
  gp::Scene scene = empty_scene(1.0 / 60.0);
  scene.bodies.push_back(ball("a", {-2.0, 0.0}, {2.0, 0.0}, 1.0, 1.0));
  scene.bodies.push_back(ball("b", {2.0, 0.0}, {-2.0, 0.0}, 1.0, 0.0));
  for (PeerEngine engine : {PeerEngine::Chipmunk, PeerEngine::Box2d}) {
    auto world = gp::peers::make_peer(engine, gp::peers::peer_scene(scene));
    for (int n = 0; n < 90; ++n) world->step(scene.dt);  // they touch at t = 0.75 s
    INFO(gp::peers::engine_name(engine));
    CHECK_THAT(world->state(0).velocity.x(), WithinAbs(-2.0, 1e-5));
    CHECK_THAT(world->state(1).velocity.x(), WithinAbs(2.0, 1e-5));
    CHECK_THAT(world->state(0).velocity.y(), WithinAbs(0.0, 1e-9));
    CHECK(world->state(0).position.x() < world->state(1).position.x());
  }
}

TEST_CASE("Chipmunk2D as its users run it multiplies the elasticities: C_R = 1 × 0",
          "[NFR:Correctness][peers]") {
  // The head-on collision above, perfectly inelastic under Chipmunk's own rule: equal masses
  // meeting at ±2 m/s both stop (momentum zero, C_R = 0).
  gp::Scene scene = empty_scene(1.0 / 60.0);
  scene.bodies.push_back(ball("a", {-2.0, 0.0}, {2.0, 0.0}, 1.0, 1.0));
  scene.bodies.push_back(ball("b", {2.0, 0.0}, {-2.0, 0.0}, 1.0, 0.0));
  auto world = gp::peers::make_peer(PeerEngine::Chipmunk,
                                    gp::peers::peer_scene(scene, gp::peers::PeerConfig::Default));
  for (int n = 0; n < 90; ++n) world->step(scene.dt);
  CHECK_THAT(world->state(0).velocity.x(), WithinAbs(0.0, 1e-5));
  CHECK_THAT(world->state(1).velocity.x(), WithinAbs(0.0, 1e-5));
}

TEST_CASE("Peers combine friction as the geometric mean, as our engine does",
          "[NFR:Correctness][peers]") {
  // A box sliding at 2 m/s on a static floor, μ = 0.9 on the box and 0.1 on the floor: μ = 0.3,
  // so friction slows it by μ g = 2.943 m/s² (Chipmunk's product 0.09 would give 0.883 m/s²).
  gp::Scene scene = empty_scene(1.0 / 60.0);
  scene.settings.gravity = {0.0, -9.81};
  gp::BodyDef box = box_body("box", 1.0, 1.0, {0.0, 0.5}, 0.9);
  box.velocity = {2.0, 0.0};
  scene.bodies = {floor_box(100.0, 0.1), box};
  for (PeerEngine engine : {PeerEngine::Chipmunk, PeerEngine::Box2d}) {
    auto world = gp::peers::make_peer(engine, gp::peers::peer_scene(scene));
    for (int n = 0; n < 30; ++n) world->step(scene.dt);  // 0.5 s, still sliding
    INFO(gp::peers::engine_name(engine));
    CHECK_THAT(world->state(1).velocity.x(), WithinAbs(2.0 - 0.3 * 9.81 * 0.5, 0.05));
  }
}

TEST_CASE("Box2D keeps a plank exactly two skins thick whole: it rests grown by the skin",
          "[NFR:Correctness][peers]") {
  // A 1 m × 2 cm plank: moved in by Box2D's skin (1 cm) on each side it would have no thickness,
  // which b2PolygonShape::Set cannot take; it keeps its own vertices, so its bottom sits
  // 2 cm below its centre, less Box2D's 5 mm resting overlap (b2_linearSlop): centre at 1.5 cm.
  gp::Scene scene = empty_scene(1.0 / 60.0);
  scene.settings.gravity = {0.0, -10.0};
  scene.bodies = {floor_box(10.0, 0.0), box_body("plank", 1.0, 0.02, {0.0, 0.05}, 0.0)};
  auto world = gp::peers::make_peer(PeerEngine::Box2d, gp::peers::peer_scene(scene));
  for (int n = 0; n < 120; ++n) world->step(scene.dt);
  CHECK_THAT(world->state(1).position.y(), WithinAbs(0.015, 1e-3));
  CHECK_THAT(world->state(1).velocity.y(), WithinAbs(0.0, 1e-3));
}

}  // namespace test_peer_collisions
}  // namespace
