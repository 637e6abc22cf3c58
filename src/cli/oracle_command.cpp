// `gamephysics oracle`: a scene file integrated by the SUNDIALS oracle (verification/oracle),
// written as the same trajectory CSV as `gamephysics simulate`, with its impacts, to check a
// simulation against.
#include <exception>
#include <iostream>
#include <memory>
#include <vector>

#include "cli/commands.hpp"
#include "cli/partial_file.hpp"
#include "engine/output/output_times.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene/input_error.hpp"
#include "verification/oracle/oracle.hpp"
#include "verification/oracle_csv.hpp"

namespace gp::cli {

int oracle(const OracleCommandOptions& options) {
  const std::string file = options.scene.string();
  verification::OracleOptions settings;
  const auto method = verification::oracle_method_from_name(options.method);
  if (!method) {
    std::cerr << "error: oracle: --method must be cvode-adams, cvode-bdf, arkode-erk or "
                 "time-stepping, got "
              << options.method << "\n";
    return kBadInput;
  }
  settings.method = *method;
  settings.rtol = options.rtol.value_or(settings.rtol);
  settings.atol = options.atol.value_or(settings.atol);
  settings.step = options.step.value_or(settings.step);
  Scene scene;
  std::unique_ptr<PartialFile> out, events;
  verification::OracleResult result;
  try {
    scene = load_scene(options.scene, options.overrides);
    // Opened before the run, so that a bad path fails at once rather than after it.
    out = std::make_unique<PartialFile>(options.out);
    if (options.events) events = std::make_unique<PartialFile>(*options.events);
    const OutputTimes instants(scene.duration, scene.output_dt);
    std::vector<double> times(instants.size());
    for (std::size_t k = 0; k < instants.size(); ++k) times[k] = instants[k];
    result = verification::run_oracle(scene, times, settings);
  } catch (const std::exception& e) {  // InputError, OracleDomainError, std::invalid_argument
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kBadInput;
  }
  try {
    verification::write_trajectory(out->stream(), scene, result);
    if (events) verification::write_impacts(events->stream(), scene, result);
    out->commit();
    if (events) events->commit();
  } catch (const std::exception& e) {  // the output could not be written
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kRunFailed;
  }
  std::cout << "wrote " << options.out.string() << ": " << scene.bodies.size()
            << " bodies from t = 0 to " << scene.duration << " s by "
            << verification::oracle_method_name(settings.method);
  if (settings.method == verification::OracleMethod::TimeStepping) {
    std::cout << " (step " << settings.step << " s, " << result.steps << " steps), deepest overlap "
              << result.largest_drift << " m\n";
  } else {
    std::cout << " (rtol " << settings.rtol << ", atol " << settings.atol << ", " << result.steps
              << " steps), " << result.events.size() << " impacts, " << result.contact_changes
              << " changes of contact, largest drift " << result.largest_drift << " m\n";
  }
  return 0;
}

}  // namespace gp::cli
