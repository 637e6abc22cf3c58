// `gamephysics peer`: a scene file run by a peer engine (verification/peers), written as the same
// trajectory CSV as `gamephysics simulate`, to compare the two row by row.
#include <exception>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/partial_file.hpp"
#include "scene/input_error.hpp"
#include "verification/peers/peer_run.hpp"
#include "verification/peers/peer_trajectory.hpp"

namespace gp::cli {

int peer(const PeerOptions& options) {
  const std::string file = options.scene.string();
  const auto engine = peers::engine_from_name(options.engine);
  if (!engine) {
    std::cerr << "error: peer: --engine must be " << peers::engine_choices() << ", got "
              << options.engine << "\n";
    return kBadInput;
  }
  const auto config = peers::config_from_name(options.config);
  if (!config) {
    std::cerr << "error: peer: --config must be default or matched, got " << options.config << "\n";
    return kBadInput;
  }
  Scene scene;
  std::unique_ptr<peers::PeerWorld> world;
  std::unique_ptr<PartialFile> out;
  try {
    scene = load_scene(options.scene, options.overrides);
    world = peers::make_peer(*engine, peers::peer_scene(scene, *config));
    out = std::make_unique<PartialFile>(options.out);
  } catch (const InputError& e) {
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kBadInput;
  }
  try {
    peers::PeerTrajectoryCsv csv(out->stream());
    peers::run_peer(*world, scene, [&](double t) { csv.write(t, *world); });
    out->commit();
  } catch (const std::exception& e) {  // the output could not be written
    std::cerr << "error: " << file << ": " << e.what() << "\n";
    return kRunFailed;
  }
  std::cout << world->describe() << "\nwrote " << options.out.string() << ": "
            << world->body_count() << " bodies from t = 0 to " << scene.duration << " s\n";
  return 0;
}

}  // namespace gp::cli
