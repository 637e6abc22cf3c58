#pragma once
// A scene file (docs/scene-format.md): the settings, the time stepping and the bodies of a run,
// read from JSON and checked (FR:Input-Initial-Conditions, FR:Input-Surface-Properties,
// FR:Verify-Physical_Constraints).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/body.hpp"
#include "scene/settings.hpp"

namespace gp {

struct Scene {
  Settings settings;
  double dt;         ///< s, > 0: the time step
  double duration;   ///< s, ≥ 0: the run covers [0, duration]
  double output_dt;  ///< s, > 0: the interval between output instants
  std::vector<BodyDef> bodies;
};

/// Values that replace the file's (the command line's options). They are put into the document
/// before it is read, so that they are checked like the file's own values and a file may leave
/// out what they give.
struct SceneOverrides {
  std::optional<std::string> integrator;
  std::optional<double> dt;         ///< s
  std::optional<double> duration;   ///< s
  std::optional<double> output_dt;  ///< s
};

/// Reads and checks the scene in `file`. Throws InputError naming the JSON path of the first
/// fault ("bodies[3].mass", "dt"; "line L, column C" for a syntax error; "(file)" for the file as
/// a whole). The SRS data constraints on bodies are checked when they are added to a space
/// (the engine's build_space).
Scene load_scene(const std::filesystem::path& file, const SceneOverrides& overrides = {});

/// The same reading and checks for the text of a scene file already in memory (the fuzzer and
/// the replay of its inputs feed bytes, not files). Throws InputError as load_scene does.
Scene parse_scene(const std::string& text, const SceneOverrides& overrides = {});

}  // namespace gp
