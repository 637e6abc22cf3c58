#include "verification/fuzz/scene_input.hpp"

#include <algorithm>
#include <sstream>

#include "engine/numerical_error.hpp"
#include "engine/output/trajectory.hpp"
#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene/input_error.hpp"
#include "scene/scene.hpp"

namespace gp::fuzz {

namespace {

std::size_t shape_count(const Scene& scene) {
  std::size_t count = 0;
  for (const BodyDef& body : scene.bodies) count += body.shapes.size();
  return count;
}

/// The scene cut to the limits: at most max_steps steps and max_outputs output instants (run_steps
/// takes at least one step per output interval, so both bound the work), and a solver doing at
/// most the limits' work a step.
Scene bounded(Scene scene, const SceneInputLimits& limits) {
  scene.duration = std::min(scene.duration, limits.max_steps * scene.dt);
  scene.output_dt = std::max(scene.output_dt, scene.duration / limits.max_outputs);
  Settings& settings = scene.settings;
  settings.velocity_iterations = std::min(settings.velocity_iterations, limits.max_passes);
  settings.position_iterations = std::min(settings.position_iterations, limits.max_passes);
  settings.direct_solve_points = std::min(settings.direct_solve_points, limits.max_direct_points);
  settings.direct_solve_uneven_points =
      std::min(settings.direct_solve_uneven_points, limits.max_direct_points);
  settings.direct_solve_resting_points =
      std::min(settings.direct_solve_resting_points, limits.max_direct_points);
  return scene;
}

}  // namespace

SceneInputOutcome run_scene_input(const std::string& text, const SceneInputLimits& limits) {
  try {
    // parse_scene checks the settings as given, before bounded() cuts them; build_space checks
    // the bodies, which bounded() leaves as they are.
    const Scene scene = parse_scene(text);
    if (scene.bodies.size() > limits.max_bodies || shape_count(scene) > limits.max_shapes) {
      build_space(scene);
      return SceneInputOutcome::kRan;
    }
    const Scene run = bounded(scene, limits);
    const auto space = build_space(run);
    std::ostringstream csv_text;
    TrajectoryCsv csv(csv_text);
    run_scene(*space, run, [&](double t) { csv.write(t, *space); });
    return SceneInputOutcome::kRan;
  } catch (const InputError&) {
    return SceneInputOutcome::kInputError;
  } catch (const NumericalError&) {
    return SceneInputOutcome::kNumericalError;
  }
}

std::string outcome_name(SceneInputOutcome outcome) {
  switch (outcome) {
    case SceneInputOutcome::kRan:
      return "ran";
    case SceneInputOutcome::kInputError:
      return "input_error";
    case SceneInputOutcome::kNumericalError:
      return "numerical_error";
  }
  return "unknown";
}

}  // namespace gp::fuzz
