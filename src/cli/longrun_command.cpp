// `gamephysics longrun`: one long run of a scene file (verification/long_run), its figures and
// its checks, the rows `gamephysics verify` reports for the shipped rain and pyramid.
#include <iostream>

#include "cli/commands.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene/input_error.hpp"
#include "verification/long_run/long_run.hpp"

namespace gp::cli {

int longrun(const LongRunOptions& options) {
  const std::string file = options.scene.string();
  Scene scene;
  try {
    scene = load_scene(options.scene);
    if (options.bodies) scene = verification::first_bodies(scene, *options.bodies);
    build_space(scene);  // the data constraints, before the run
  } catch (const InputError& e) {
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kBadInput;
  }
  const verification::Box box = verification::starting_box(scene, verification::kBoxMargin);
  std::cout << file << ": " << scene.bodies.size() << " bodies, " << options.steps
            << " steps of dt = " << scene.dt << " s, box [" << box.lower.x() << ", "
            << box.upper.x() << "] x [" << box.lower.y() << ", " << box.upper.y() << "] m\n";
  std::cout << "  resident memory [MiB] by step:";
  // Each sample as it is taken: a run of hours shows its progress, and what it had measured
  // survives its being stopped.
  const auto result = verification::long_run(scene, options.steps, verification::kMemorySamples,
                                             box, [](const verification::MemorySample& sample) {
                                               std::cout << " " << sample.step << ":"
                                                         << verification::figure(sample.rss_mib)
                                                         << std::flush;
                                             });
  std::cout << "\n";
  bool passed = true;
  for (const auto& row : verification::long_run_rows(file, result)) {
    std::cout << "  " << (row.passed ? "ok    " : "FAILED") << " " << row.name << ": "
              << row.measured << " (" << row.criterion << ")\n";
    passed = passed && row.passed;
  }
  return passed ? 0 : kRunFailed;
}

}  // namespace gp::cli
