// A peer run takes our run's steps and output instants and writes our trajectory format.
#include <catch2/catch.hpp>

#include <numbers>
#include <sstream>

#include "engine/output/trajectory.hpp"
#include "peer_scenes.hpp"
#include "verification/peers/peer_run.hpp"
#include "verification/peers/peer_trajectory.hpp"

using Catch::Matchers::WithinAbs;
using gp::peers::PeerEngine;

namespace {
namespace test_peer_run {

/// A kinematic box turning clockwise over a static floor, and a ball dropped beside it.
gp::Scene mixed_scene() {
  gp::Scene scene = gp::peers::testing::empty_scene(0.03);
  scene.duration = 0.1;
  scene.output_dt = 0.05;
  scene.settings.gravity = {0.0, -9.81};
  gp::BodyDef floor;
  floor.name = "floor";
  floor.type = gp::BodyType::Static;
  floor.shapes.push_back({gp::Shape::segment({-5.0, 0.0}, {5.0, 0.0}, 0.1)});
  gp::BodyDef spinner;
  spinner.name = "spinner";
  spinner.type = gp::BodyType::Kinematic;
  spinner.position = {-2.0, 1.0};
  spinner.velocity = {1.0, 0.0};
  spinner.angular_velocity = -1.0;
  spinner.shapes.push_back({gp::Shape::box(1.0, 0.5)});
  scene.bodies = {floor, spinner, gp::peers::testing::ball("ball", {2.0, 3.0}, {0, 0}, 1.0, 0)};
  return scene;
}

TEST_CASE("A peer run stops on every output instant and writes the trajectory CSV",
          "[NFR:Correctness][peers]") {
  const gp::Scene scene = mixed_scene();
  for (PeerEngine engine : {PeerEngine::Chipmunk, PeerEngine::Box2d}) {
    INFO(gp::peers::engine_name(engine));
    auto world = gp::peers::make_peer(engine, gp::peers::peer_scene(scene));
    std::ostringstream csv;
    gp::peers::PeerTrajectoryCsv writer(csv);
    std::vector<double> instants;
    gp::peers::run_peer(*world, scene, [&](double t) {
      instants.push_back(t);
      writer.write(t, *world);
    });
    CHECK(instants == std::vector<double>{0.0, 0.05, 0.1});
    std::istringstream lines(csv.str());
    std::string line;
    std::getline(lines, line);
    CHECK(line == gp::kTrajectoryHeader);
    int rows = 0;
    while (std::getline(lines, line)) ++rows;
    CHECK(rows == 3 * 3);
    // Steps of 0.03 s shortened to end on 0.05 s and 0.1 s: the ball has fallen ½ g t² (within
    // the O(h) of symplectic Euler), the kinematic box moved 0.1 m and turned to 2π − 0.1.
    CHECK_THAT(world->state(2).position.y(), WithinAbs(3.0 - 0.5 * 9.81 * 0.01, 0.02));
    CHECK_THAT(world->state(1).position.x(), WithinAbs(-1.9, 1e-6));
    CHECK_THAT(world->state(1).angle, WithinAbs(2.0 * std::numbers::pi - 0.1, 1e-6));
    CHECK(world->state(0).position == gp::Vec2(0.0, 0.0));
    CHECK_THAT(world->describe(),
               Catch::Contains(engine == PeerEngine::Chipmunk ? "Chipmunk2D" : "Box2D"));
  }
}

TEST_CASE("Default peers keep their own iterations, matched ones take ours, a scene's wins",
          "[NFR:Correctness][peers]") {
  using gp::peers::PeerConfig;
  gp::Scene scene = mixed_scene();
  const auto as_is = gp::peers::peer_scene(scene, PeerConfig::Default);
  CHECK_FALSE(as_is.velocity_iterations);
  CHECK_THAT(
      gp::peers::make_peer(PeerEngine::Box2d, as_is)->describe(),
      Catch::Contains("8 velocity and 3 position iterations") && Catch::Contains("sleeping on"));
  CHECK_THAT(gp::peers::make_peer(PeerEngine::Chipmunk, as_is)->describe(),
             Catch::Contains("collision slop 0.1 m") && Catch::Contains("as products"));
  const auto matched = gp::peers::peer_scene(scene, PeerConfig::Matched);
  CHECK_THAT(
      gp::peers::make_peer(PeerEngine::Box2d, matched)->describe(),
      Catch::Contains("10 velocity and 4 position iterations") && Catch::Contains("sleeping off"));
  CHECK_THAT(gp::peers::make_peer(PeerEngine::Chipmunk, matched)->describe(),
             Catch::Contains("collision slop 0.0002 m") && Catch::Contains("as ours"));
  scene.settings.velocity_iterations = 20;
  scene.settings.position_iterations = 6;
  for (PeerConfig config : {PeerConfig::Default, PeerConfig::Matched}) {
    const auto peer = gp::peers::peer_scene(scene, config);
    INFO(gp::peers::config_name(config));
    CHECK_THAT(gp::peers::make_peer(PeerEngine::Box2d, peer)->describe(),
               Catch::Contains("20 velocity and 6 position iterations"));
    CHECK_THAT(gp::peers::make_peer(PeerEngine::Chipmunk, peer)->describe(),
               Catch::Contains("20 iterations"));
  }
}

TEST_CASE("Peers are given our mass setup: infinite mass for static and kinematic bodies",
          "[NFR:Correctness][peers]") {
  const auto peer = gp::peers::peer_scene(mixed_scene());
  REQUIRE(peer.bodies.size() == 3);
  CHECK(std::isinf(peer.bodies[0].mass));
  CHECK(std::isinf(peer.bodies[1].mass));
  CHECK_THAT(peer.bodies[2].mass, WithinAbs(1.0, 1e-15));
  // A disc: I = m r² / 2 about its centre.
  CHECK_THAT(peer.bodies[2].moment, WithinAbs(0.125, 1e-15));
  CHECK(peer.bodies[1].start.angular_velocity == -1.0);
}

}  // namespace test_peer_run
}  // namespace
