// The checks of a long run (verification/long_run) can fail: a body thrown out of its box is
// caught, the box of rain1000 is its walls and starting heights, and memory growth is measured
// from the first tenth of the run. The short rain here is what `verify --quick` runs longer.
#include <catch2/catch.hpp>
#include <filesystem>
#include <vector>

#include "verification/long_run/long_run.hpp"

using gp::Vec2;

namespace {
namespace test_long_run {
gp::Scene rain() {
  return gp::load_scene(std::filesystem::path(GP_SOURCE_DIR) / "scenes" / "rain1000.json");
}

TEST_CASE("The box of rain1000 is its three walls and its highest ball widened by 1 m",
          "[NFR:Correctness]") {
  const auto box = gp::verification::starting_box(rain(), 1.0);
  // Walls from x = ±40 m up to 60 m, floor at 0; the top row of balls is at 5 + 24·1.5 = 41 m.
  CHECK(box.lower == Vec2(-41.0, -1.0));
  CHECK(box.upper == Vec2(41.0, 61.0));
  CHECK(box.contains({40.5, 60.5}));
  CHECK_FALSE(box.contains({0.0, 61.5}));
}

TEST_CASE("A long run finds a body that leaves its box", "[NFR:Correctness]") {
  gp::Scene scene = gp::verification::first_bodies(rain(), 2);
  scene.bodies[1].velocity = {100.0, 0.0};
  scene.bodies[1].shapes.clear();  // a point mass passes through the wall
  scene.bodies[1].mass = 1.0;
  std::vector<long> sampled_steps;
  const auto result =
      gp::verification::long_run(scene, 100, 10, gp::verification::starting_box(scene, 1.0),
                                 [&](const auto& sample) { sampled_steps.push_back(sample.step); });
  // From x = −29.25 m at 100 m/s it passes x = 41 m after 0.7025 s: in step 43 of 1/60 s.
  CHECK(result.first_outside == "body 'ball0000' at step 43");
  CHECK(result.non_finite.empty());
  CHECK(result.steps_done == 100);
  CHECK(result.memory.size() == 11);
  // The start and every tenth of the run, told as they are taken.
  CHECK(sampled_steps == std::vector<long>{0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100});
  CHECK(result.max_abs_coordinate == Approx(-29.25 + 100.0 * 100 / 60.0));
}

TEST_CASE("A short rain of 40 balls stays finite and in its box and memory",
          "[NFR:Correctness][FR:Determine-Collision-Response-Over-Time]") {
  const gp::Scene scene = gp::verification::first_bodies(rain(), 41);
  const auto result =
      gp::verification::long_run(scene, 3000, 20, gp::verification::starting_box(scene, 1.0));
  CHECK(result.non_finite.empty());
  CHECK(result.first_outside.empty());
  CHECK(result.steps_done == 3000);
  CHECK(result.memory_growth_mib() <= gp::verification::kMaxMemoryGrowthMib);
  // The balls fall from 5 m and never rise above it: |y| stays under 5 m, |x| under the walls.
  CHECK(result.max_abs_coordinate < 40.0);
}

TEST_CASE("Memory growth is counted from the first tenth of a run", "[NFR:Performance]") {
  gp::verification::LongRunResult result;
  result.memory = {{0, 10.0}, {50, 30.0}, {100, 31.0}, {500, 31.5}, {1000, 32.5}};
  // The sample at step 100 (a tenth of 1000) is the baseline: 32.5 − 31.0.
  CHECK(result.memory_growth_mib() == Approx(1.5));
}

}  // namespace test_long_run
}  // namespace
