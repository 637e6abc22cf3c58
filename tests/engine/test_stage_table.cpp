// The step runs the table of stages that --explain prints: on every shipped scene, the stages a
// step executed are exactly those the explanation lists for the passes the step ran.
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <set>
#include <string>

#include "engine/scene/scene_space.hpp"
#include "engine/space_impl.hpp"
#include "scene/scene.hpp"

namespace {
namespace test_stage_table {

std::set<std::string> listed_for(const std::vector<gp::PipelineStage>& stages,
                                 const std::string& pass) {
  std::set<std::string> out;
  for (const gp::PipelineStage& s : stages) {
    if (s.needed && s.passes.find(pass) != std::string::npos) out.insert(s.name);
  }
  return out;
}

TEST_CASE("The explanation lists exactly the stages each pass of a step executes, on every scene",
          "[FR:Simulation-Space]") {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(GP_SOURCE_DIR "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    gp::SceneOverrides shorter;
    shorter.duration = 0.5;  // long enough for contacts, impacts and resting in every scene
    shorter.output_dt = 0.5;
    const gp::Scene scene = gp::load_scene(entry.path(), shorter);
    const auto space = gp::build_space(scene);
    const std::vector<gp::PipelineStage> explained = space->pipeline();
    const gp::StepRunner& runner = gp::SpaceInternals::runner(*space);
    REQUIRE(runner.local_passes() + runner.sub_steps() == 0);
    for (double t = 0.0; t < scene.duration; t += scene.dt) space->step(scene.dt);
    INFO(entry.path().filename().string());
    const auto stages = gp::step_stages();
    std::set<std::string> executed;
    for (std::size_t i = 0; i < stages.size(); ++i) {
      if (runner.stage_runs()[i] > 0) executed.insert(std::string(stages[i].name));
    }
    // A stage the table lists for a pass that ran must have run; one it lists for no pass that
    // ran must not have.
    std::set<std::string> expected;
    if (runner.local_passes() > 0) expected.merge(listed_for(explained, "local step"));
    if (runner.sub_steps() > 0) expected.merge(listed_for(explained, "sub-steps"));
    CHECK(executed == expected);
    ++scenes;
  }
  CHECK(scenes >= 18);
}

TEST_CASE("The bounce stages are needed only while a shape has a restitution above 0",
          "[FR:Simulation-Space]") {
  const auto bounce_stages_needed = [](const gp::Space& space) {
    int needed = 0;
    for (const gp::PipelineStage& s : space.pipeline()) {
      if (s.name == "impacts among touching bodies" || s.name == "contact solver: restitution") {
        needed += s.needed ? 1 : 0;
      }
    }
    return needed;
  };
  // Every shape of the pyramid has restitution 0.
  const auto pyramid = gp::build_space(gp::load_scene(GP_SOURCE_DIR "/scenes/pyramid20.json"));
  CHECK(bounce_stages_needed(*pyramid) == 0);
  gp::BodyDef ball;
  ball.name = "ball";
  ball.position = {0.0, 30.0};
  ball.shapes.push_back({gp::Shape::circle(0.5), 0.8, 0.6});
  const gp::BodyId id = pyramid->add_body(ball);
  CHECK(bounce_stages_needed(*pyramid) == 2);
  pyramid->remove_body(id);
  CHECK(bounce_stages_needed(*pyramid) == 0);
}

TEST_CASE("Timed stages add up to no more than the steps' wall time, and untimed ones to nothing",
          "[FR:Simulation-Space]") {
  const gp::Scene scene = gp::load_scene(GP_SOURCE_DIR "/scenes/pyramid20.json", {});
  const auto space = gp::build_space(scene);
  constexpr int kSteps = 30;
  for (int k = 0; k < kSteps; ++k) space->step(scene.dt);
  for (const gp::PipelineStage& s : space->pipeline()) CHECK(s.seconds == 0.0);

  space->time_stages(true);
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < kSteps; ++k) space->step(scene.dt);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double timed = 0.0;
  for (const gp::PipelineStage& s : space->pipeline()) {
    INFO(s.name);
    // A pile's steps are local passes: each stage needed by one runs once a step.
    if (s.needed && s.passes.find("local step") != std::string::npos) {
      CHECK(s.runs == 2 * kSteps);
      CHECK(s.seconds > 0.0);
    } else {
      CHECK(s.seconds == 0.0);
    }
    timed += s.seconds;
  }
  CHECK(timed <= wall);
  // The clock reads between the stages cost well under a tenth of a pile's step.
  CHECK(timed > 0.9 * wall);
}

}  // namespace test_stage_table
}  // namespace
