// Free motion in the peer engines against each engine's own discrete closed form: both step with
// symplectic Euler, so their positions differ from x₀ + v₀t + ½gt² by O(h), each in its own way.
#include <catch2/catch.hpp>

#include "peer_scenes.hpp"
#include "verification/peers/peer_world.hpp"

using Catch::Matchers::WithinAbs;
using gp::Vec2;
using gp::peers::PeerEngine;
using gp::peers::testing::empty_scene;

namespace {
namespace test_peer_motion {

using gp::peers::testing::thrown_projectile;
using gp::peers::testing::projectile::g;
using gp::peers::testing::projectile::h;
using gp::peers::testing::projectile::steps;
using gp::peers::testing::projectile::v0;
using gp::peers::testing::projectile::x0;

TEST_CASE("Chipmunk2D moves a projectile as position-first symplectic Euler to 1e-12 m",
          "[NFR:Correctness][peers]") {
  // cpSpaceStep moves positions with the old velocity, then updates the velocity:
  // x_n = x₀ + v₀ n h + g h² n(n − 1)/2, v_n = v₀ + g n h.
  const gp::BodyState s = thrown_projectile(PeerEngine::Chipmunk)->state(0);
  const double n = steps;
  const Vec2 x = x0 + v0 * n * h + g * h * h * n * (n - 1) / 2;
  const Vec2 v = v0 + g * n * h;
  // Criteria 3 to 10 times the rounding measured (3.6e-14, 5.3e-15, 7.1e-15).
  CHECK_THAT(s.position.x(), WithinAbs(x.x(), 2e-13));
  CHECK_THAT(s.position.y(), WithinAbs(x.y(), 2e-14));
  CHECK_THAT(s.velocity.y(), WithinAbs(v.y(), 5e-14));
  CHECK(s.velocity.x() == v0.x());
}

TEST_CASE("Box2D moves a projectile as velocity-first symplectic Euler to float precision",
          "[NFR:Correctness][peers]") {
  // b2World::Step updates the velocity, then moves positions with it:
  // x_n = x₀ + v₀ n h + g h² n(n + 1)/2, v_n = v₀ + g n h; in single precision, 1e-4 relative.
  const gp::BodyState s = thrown_projectile(PeerEngine::Box2d)->state(0);
  const double n = steps;
  const Vec2 x = x0 + v0 * n * h + g * h * h * n * (n + 1) / 2;
  const Vec2 v = v0 + g * n * h;
  CHECK_THAT(s.position.x(), WithinAbs(x.x(), 1e-4 * std::abs(x.x())));
  CHECK_THAT(s.position.y(), WithinAbs(x.y(), 1e-4 * std::abs(x.y())));
  CHECK_THAT(s.velocity.y(), WithinAbs(v.y(), 1e-4 * std::abs(v.y())));
  // The other rule is 2 g h² n = 0.39 m away: the test tells the two apart.
  CHECK(std::abs(s.position.y() - (x.y() - g.y() * h * h * n)) > 0.1);
}

TEST_CASE("Peers apply constant forces, torques and a force off the centre every step",
          "[NFR:Correctness][peers]") {
  // A 2 kg box 1 m × 1 m (I = 2/6 kg·m²) pushed by F = (3, 0) N at 0.5 m above its centre and
  // turned by τ = 1 N·m: after one step of h, v = F h / m and ω = (τ − 0.5·3) h / I.
  gp::Scene scene = empty_scene(h);
  gp::BodyDef box;
  box.name = "box";
  box.shapes.push_back({gp::Shape::box(1.0, 1.0)});
  box.mass = 2.0;
  box.force = {3.0, 0.0};
  box.force_point = Vec2{0.0, 0.5};
  box.torque = 1.0;
  scene.bodies.push_back(box);
  const double I = 2.0 / 6.0;
  for (PeerEngine engine : {PeerEngine::Chipmunk, PeerEngine::Box2d}) {
    auto world = gp::peers::make_peer(engine, gp::peers::peer_scene(scene));
    world->step(h);
    const gp::BodyState s = world->state(0);
    INFO(gp::peers::engine_name(engine));
    CHECK_THAT(s.velocity.x(), WithinAbs(3.0 * h / 2.0, 1e-7));
    CHECK_THAT(s.angular_velocity, WithinAbs((1.0 - 1.5) * h / I, 1e-7));
  }
}

TEST_CASE("Peers feel pairwise gravitation applied as forces", "[NFR:Correctness][peers]") {
  // Two 1000 kg points 1 m apart with G = 1e-3: each accelerates at G m / d² = 1 m/s² towards
  // the other, so after one step of h each moves towards the other at 1 m/s² · h.
  gp::Scene scene = empty_scene(h);
  scene.settings.G = 1e-3;
  for (const double x : {-0.5, 0.5}) {
    gp::BodyDef point;
    point.name = x < 0 ? "left" : "right";
    point.position = {x, 0.0};
    point.mass = 1000.0;
    scene.bodies.push_back(point);
  }
  for (PeerEngine engine : {PeerEngine::Chipmunk, PeerEngine::Box2d}) {
    auto world = gp::peers::make_peer(engine, gp::peers::peer_scene(scene));
    world->step(h);
    INFO(gp::peers::engine_name(engine));
    CHECK_THAT(world->state(0).velocity.x(), WithinAbs(h, 1e-7));
    CHECK_THAT(world->state(1).velocity.x(), WithinAbs(-h, 1e-7));
  }
}

TEST_CASE("Peer engines are named chipmunk and box2d, their configurations default and matched",
          "[NFR:Correctness][peers]") {
  for (PeerEngine engine : {PeerEngine::Chipmunk, PeerEngine::Box2d}) {
    CHECK(gp::peers::engine_from_name(gp::peers::engine_name(engine)) == engine);
  }
  CHECK_FALSE(gp::peers::engine_from_name("bullet"));
  for (auto config : {gp::peers::PeerConfig::Default, gp::peers::PeerConfig::Matched}) {
    CHECK(gp::peers::config_from_name(gp::peers::config_name(config)) == config);
  }
  CHECK_FALSE(gp::peers::config_from_name("release"));
}

}  // namespace test_peer_motion
}  // namespace
