// The well-posed measures of a chaotic pile (verification/suite/pile_measures.hpp) on a run
// written by hand: energy, time to settle and settled profile, worked out below.
#include <catch2/catch.hpp>

#include "verification/suite/pile_measures.hpp"

namespace {
namespace test_pile_measures {

constexpr double kG = 9.81;

// Two discs of 1 kg and radius 0.5 m (I = ½ m r² = 0.125 kg·m²) over a static ground.
gp::Scene two_discs() {
  gp::Scene scene{};
  scene.settings.gravity = {0.0, -kG};
  gp::BodyDef ground;
  ground.name = "ground";
  ground.type = gp::BodyType::Static;
  ground.shapes.push_back({gp::Shape::segment({-10.0, 0.0}, {10.0, 0.0})});
  scene.bodies.push_back(ground);
  for (const char* name : {"a", "b"}) {
    gp::BodyDef disc;
    disc.name = name;
    disc.mass = 1.0;
    disc.shapes.push_back({gp::Shape::circle(0.5)});
    scene.bodies.push_back(disc);
  }
  return scene;
}

gp::BodyState at(double y, gp::Vec2 velocity = gp::Vec2::Zero(), double omega = 0.0) {
  return {{0.0, y}, 0.0, velocity, omega};
}

TEST_CASE("pile measures: energy, time to settle and profile of a run worked by hand",
          "[verify][pile]") {
  gp::verification::Trajectory run;
  run.times = {0.0, 1.0, 2.0};
  run.states = {{at(0.0), at(3.0), at(1.0)},
                {at(0.0), at(2.0, {0.0, -2.0}, 4.0), at(1.0)},
                {at(0.0), at(1.0), at(1.0, {0.01, 0.0})}};
  const auto m = gp::verification::measure_pile(two_discs(), run);
  // The drop: disc a could fall 2 m to b's height: 2 g J.
  CHECK(m.drop == Approx(2.0 * kG));
  // E = Σ ½ m v² + ½ I ω² + m g y: 4 g; ½·4 + ½·0.125·16 + 3 g = 3 + 3 g; ½·1e-4 + 2 g.
  REQUIRE(m.energy.size() == 3);
  CHECK(m.energy[0] == Approx(4.0 * kG));
  CHECK(m.energy[1] == Approx(3.0 + 3.0 * kG));
  CHECK(m.energy[2] == Approx(0.5e-4 + 2.0 * kG));
  // Kinetic 3 J at 1 s, 5e-5 J (below 1e-3 of the drop, 0.0196 J) from 2 s.
  CHECK(m.settle_time == 2.0);
  CHECK(m.profile == std::vector<double>{1.0, 1.0});

  gp::verification::Trajectory other = run;
  other.states[1][1].velocity = gp::Vec2::Zero();
  other.states[1][1].angular_velocity = 0.0;
  other.states[2][2].position.y() = 1.25;
  const auto d =
      gp::verification::pile_differences(gp::verification::measure_pile(two_discs(), other), m);
  // At 1 s it has no kinetic energy (3 J less); at 2 s b stands 0.25 m higher (+0.25 g J).
  CHECK(d.energy == Approx(3.0 / (2.0 * kG)));
  CHECK(d.settled_energy == Approx(0.25 * kG / (2.0 * kG)));
  CHECK(d.settle_time == 2.0);  // its kinetic energy never reaches the threshold: 0 s
  CHECK(d.profile == Approx(0.25));
}

}  // namespace test_pile_measures
}  // namespace
