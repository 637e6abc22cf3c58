// `gamephysics view`: a scene file run and written as one self-contained HTML page that plays it
// back (verification/viewer), optionally over the SUNDIALS oracle's solution.
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "cli/commands.hpp"
#include "cli/partial_file.hpp"
#include "engine/output/output_times.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene/input_error.hpp"
#include "verification/oracle/oracle.hpp"
#include "verification/viewer/recording.hpp"
#include "verification/viewer/viewer_page.hpp"

namespace gp::cli {

namespace {

// The scene's free-text "description", which load_scene does not keep; the file is already known
// to be valid JSON.
std::string description_of(const std::filesystem::path& file) {
  const auto document = nlohmann::json::parse(std::ifstream(file));
  const auto it = document.find("description");
  return it != document.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace

int view(const ViewOptions& options) {
  const std::string file = options.scene.string();
  Scene scene;
  std::unique_ptr<Space> space;
  std::unique_ptr<PartialFile> out;
  std::optional<verification::OracleResult> oracle;
  const verification::OracleOptions oracle_settings;
  try {
    scene = load_scene(options.scene, options.overrides);
    space = build_space(scene);
    out = std::make_unique<PartialFile>(options.out);
    if (options.oracle) {
      // A scene outside the oracle's domain is bad input, as for `gamephysics oracle`.
      const OutputTimes instants(scene.duration, scene.output_dt);
      std::vector<double> times(instants.size());
      for (std::size_t k = 0; k < instants.size(); ++k) times[k] = instants[k];
      oracle = verification::run_oracle(scene, times, oracle_settings);
    }
  } catch (const std::exception& e) {  // InputError, OracleDomainError
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kBadInput;
  }
  try {
    const verification::Recording recording = verification::record_run(*space, scene);
    const verification::ViewerRun run{
        options.scene.filename().string(),
        description_of(options.scene),
        scene,
        *space,
        recording,
        oracle ? &*oracle : nullptr,
        std::string(verification::oracle_method_name(oracle_settings.method)),
        options.audit};
    verification::write_viewer_page(out->stream(), run);
    out->commit();
    std::cout << "wrote " << options.out.string() << ": " << space->body_count() << " bodies, "
              << recording.frames.size() << " frames from t = 0 to " << scene.duration << " s, "
              << recording.impacts.size() << " impacts" << (oracle ? ", with the oracle" : "")
              << "\n";
  } catch (const std::exception& e) {  // NumericalError, or the page could not be written
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kRunFailed;
  }
  return 0;
}

}  // namespace gp::cli
