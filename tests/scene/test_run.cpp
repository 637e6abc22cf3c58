// A run stops exactly on every output instant k·output_dt and on the final time.
#include <catch2/catch.hpp>
#include <string>
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

// The states of every body at each instant of a run of `scene_text` reporting every
// `output_dt` seconds; the clock must be at each instant to within rounding.
std::vector<std::vector<gp::BodyState>> states_every(const std::string& scene_text,
                                                     double output_dt) {
  gp::Scene scene = gp::test::load(scene_text);
  scene.output_dt = output_dt;
  const auto space = gp::build_space(scene);
  std::vector<std::vector<gp::BodyState>> states;
  gp::run_scene(*space, scene, [&](double t) {
    CHECK(space->time() == Approx(t).margin(1e-12));
    std::vector<gp::BodyState>& now = states.emplace_back();
    for (gp::BodyId b = 0; b < space->body_count(); ++b) now.push_back(space->state(b));
  });
  return states;
}

TEST_CASE("How often a run reports does not change its steps when output_dt is a multiple of dt",
          "[FR:Simulation-Space]") {
  // 1/60 s steps do not add up to 0.1 s or 1 s to the last bit: a step made to land on each
  // instant would differ from dt by a rounding, which three discs falling onto a floor and
  // onto each other then carry on.
  const std::string scene = R"({"gravity": [0, -9.81], "dt": 0.016666666666666666,
      "duration": 2.0, "bodies": [
        {"name": "floor", "type": "static", "position": [0, 0],
         "shapes": [{"type": "segment", "a": [-5, 0], "b": [5, 0], "friction": 0.6}]},
        {"name": "a", "position": [-0.5, 0.7], "velocity": [0.1, 0],
         "shapes": [{"type": "circle", "radius": 0.5, "friction": 0.6}]},
        {"name": "b", "position": [0.5, 0.8], "angular_velocity": 1,
         "shapes": [{"type": "circle", "radius": 0.5, "friction": 0.6}]},
        {"name": "c", "position": [0.05, 2.5],
         "shapes": [{"type": "circle", "radius": 0.5, "friction": 0.6}]}]})";
  const auto every_step = states_every(scene, 0.016666666666666666);
  const auto every_tenth = states_every(scene, 0.1);
  const auto every_second = states_every(scene, 1.0);
  REQUIRE(every_step.size() == 121);
  REQUIRE(every_tenth.size() == 21);
  REQUIRE(every_second.size() == 3);
  for (std::size_t k = 0; k < every_tenth.size(); ++k) {
    for (std::size_t b = 0; b < every_tenth[k].size(); ++b) {
      const gp::BodyState& step = every_step[6 * k][b];
      const gp::BodyState& tenth = every_tenth[k][b];
      CHECK(step.position == tenth.position);
      CHECK(step.angle == tenth.angle);
      CHECK(step.velocity == tenth.velocity);
      CHECK(step.angular_velocity == tenth.angular_velocity);
      if (k % 10 == 0) CHECK(every_second[k / 10][b].position == tenth.position);
    }
  }
  // The discs did meet: the top one lies on the two below (1.37 m up while they touch; it
  // pushes them apart as it sinks), not on the floor (0.5 m).
  CHECK(every_second[2][3].position.y() > 1.0);
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
