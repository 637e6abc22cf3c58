// A run stops exactly on every output instant k·output_dt and on the final time.
#include <catch2/catch.hpp>
#include <vector>

#include "engine/output/output_times.hpp"
#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene_files.hpp"

namespace {
namespace test_run {

std::vector<double> instants(double duration, double output_dt) {
  const gp::OutputTimes times(duration, output_dt);
  std::vector<double> result;
  for (std::size_t k = 0; k < times.size(); ++k) result.push_back(times[k]);
  return result;
}

TEST_CASE("Output instants are k * output_dt and the final time", "[FR:Simulation-Space]") {
  CHECK(instants(1.0, 0.25) == std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0});
  // 0.3 is not a multiple of 0.1 in binary (3 × 0.1 = 0.30000000000000004): the end comes once.
  CHECK(instants(0.3, 0.1) == std::vector<double>{0.0, 0.1, 0.2, 0.3});
  // The end is not a multiple: it is an instant of its own.
  CHECK(instants(1.0, 0.3) == std::vector<double>{0.0, 0.3, 0.6, 0.3 * 3, 1.0});
  CHECK(instants(0.5, 2.0) == std::vector<double>{0.0, 0.5});
  CHECK(instants(0.0, 0.1) == std::vector<double>{0.0});
  // An end closer to 0 than the tolerance still reports t = 0 and the end.
  CHECK(instants(1e-12, 1.0) == std::vector<double>{0.0, 1e-12});
}

TEST_CASE("Every instant is exactly k * output_dt over many intervals", "[FR:Simulation-Space]") {
  const double output_dt = 0.01;
  const gp::OutputTimes times(2.0, output_dt);
  REQUIRE(times.size() == 201);
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    CHECK(times[k] == static_cast<double>(k) * output_dt);
  }
  CHECK(times[200] == 2.0);
}

TEST_CASE("A run stops on every output instant, and a step never crosses one",
          "[FR:Calculate-Translation-Over-Time]") {
  // dt does not divide output_dt: steps of 0.03 are shortened to end on each multiple of 0.1.
  // Under constant acceleration velocity Verlet is exact, so the state shows the time reached.
  const gp::Scene scene = gp::test::load(R"({"gravity": [0, -9.81], "dt": 0.03,
      "duration": 1.05, "output_dt": 0.1,
      "bodies": [{"name": "p", "position": [0, 0], "velocity": [1, 5], "mass": 1}]})");
  const auto space = gp::build_space(scene);
  std::vector<double> reported;
  gp::run_scene(*space, scene, [&](double t) {
    reported.push_back(t);
    const gp::BodyState s = space->state(0);
    CHECK(space->time() == Approx(t).margin(1e-12));
    CHECK(s.position.x() == Approx(t).margin(1e-12));
    CHECK(s.position.y() == Approx(5 * t - 0.5 * 9.81 * t * t).margin(1e-12));
    CHECK(s.velocity.y() == Approx(5 - 9.81 * t).margin(1e-12));
  });
  CHECK(reported == instants(1.05, 0.1));
  CHECK(reported.back() == 1.05);
}

TEST_CASE("A scene of duration 0 reports its initial state only", "[FR:Simulation-Space]") {
  const gp::Scene scene = gp::test::load(R"({"dt": 0.01, "duration": 0,
      "bodies": [{"name": "p", "position": [0, 0], "velocity": [1, 0], "mass": 1}]})");
  const auto space = gp::build_space(scene);
  int calls = 0;
  gp::run_scene(*space, scene, [&](double t) {
    ++calls;
    CHECK(t == 0.0);
  });
  CHECK(calls == 1);
  CHECK(space->time() == 0.0);
}

}  // namespace test_run
}  // namespace
