// `gamephysics simulate`: a scene file in, its trajectory out (docs/scene-format.md).
#include <chrono>
#include <exception>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "cli/commands.hpp"
#include "cli/lane_limit.hpp"
#include "cli/partial_file.hpp"
#include "cli/thread_limit.hpp"
#include "engine/output/output_times.hpp"
#include "engine/output/trajectory.hpp"
#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene/input_error.hpp"

namespace gp::cli {

namespace {

void explain(const std::string& file, const Scene& scene, const Space& space) {
  std::cout << "pipeline of a step of " << file << " (" << space.body_count()
            << " bodies, dt = " << scene.dt << " s, "
            << OutputTimes(scene.duration, scene.output_dt).size() << " output instants from 0 to "
            << scene.duration << " s):\n";
  int number = 0;
  std::string skipped;
  for (const PipelineStage& stage : space.pipeline()) {
    if (!stage.needed) {
      skipped += (skipped.empty() ? "" : ", ") + stage.name;
      continue;
    }
    std::cout << "  " << ++number << ". " << stage.name;
    if (!stage.srs_ids.empty()) std::cout << "  [" << stage.srs_ids << "]";
    std::cout << "  (" << stage.passes << ")\n     " << stage.description << "\n";
  }
  if (!skipped.empty()) std::cout << "  not needed by this scene, skipped: " << skipped << "\n";
}

// After a run of `seconds` [s] with --explain: the wall time of each stage that ran, and what the
// run spent outside them (setting up, writing the output).
void report_stage_times(const Space& space, double seconds) {
  std::cout << "time per stage, wall clock, of a run of " << std::fixed << std::setprecision(3)
            << seconds << " s:\n";
  double staged = 0.0;
  for (const PipelineStage& stage : space.pipeline()) {
    if (stage.runs == 0) continue;
    staged += stage.seconds;
    std::cout << "  " << std::left << std::setw(52) << stage.name << std::right << std::setw(9)
              << stage.runs << " runs " << std::setw(9) << std::setprecision(3) << stage.seconds
              << " s " << std::setw(9) << std::setprecision(1)
              << 1e6 * stage.seconds / static_cast<double>(stage.runs) << " µs/run " << std::setw(5)
              << 100.0 * stage.seconds / seconds << "%\n";
  }
  std::cout << "  " << std::left << std::setw(52) << "outside the stages (output, between steps)"
            << std::right << std::setw(24) << std::setprecision(3) << seconds - staged << " s "
            << std::setw(21) << std::setprecision(1) << 100.0 * (seconds - staged) / seconds
            << "%\n";
  std::cout << std::defaultfloat << std::setprecision(6);
}

}  // namespace

int simulate(const SimulateOptions& options) {
  const std::string file = options.scene.string();
  if (!options.out && !options.explain) {
    std::cerr << "error: simulate: give --out OUT.csv (or --explain)\n";
    return kBadInput;
  }
  Scene scene;
  std::unique_ptr<Space> space;
  std::unique_ptr<PartialFile> out;
  std::optional<tbb::global_control> threads;
  try {
    limit_threads(threads, options.threads);
    limit_lanes(options.lanes);
    scene = load_scene(options.scene, options.overrides);
    space = build_space(scene);
    if (options.explain) explain(file, scene, *space);
    // The space holds the bodies now; their definitions would stay in memory for the whole run
    // (about 680 bytes a box in a pile).
    std::vector<BodyDef>().swap(scene.bodies);
    if (!options.out) return 0;
    out = std::make_unique<PartialFile>(*options.out);
  } catch (const InputError& e) {
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kBadInput;
  }
  double run_seconds = 0.0;
  try {
    TrajectoryCsv csv(out->stream());
    space->time_stages(options.explain);
    const auto start = std::chrono::steady_clock::now();
    run_scene(*space, scene, [&](double t) { csv.write(t, *space); });
    run_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out->commit();
  } catch (const std::exception& e) {  // NumericalError, or the output could not be written
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kRunFailed;
  }
  std::cout << "wrote " << options.out->string() << ": " << space->body_count()
            << " bodies from t = 0 to " << scene.duration << " s\n";
  if (options.explain) report_stage_times(*space, run_seconds);
  return 0;
}

}  // namespace gp::cli
