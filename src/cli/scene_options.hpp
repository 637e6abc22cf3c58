#pragma once
// The options every command that runs a scene file shares: the file, and what overrides it.

#include <CLI/CLI.hpp>
#include <filesystem>

#include "scene/scene.hpp"

namespace gp::cli {

/// Which of a scene's settings a command lets the command line override (bits).
enum SceneOverride : unsigned {
  kIntegrator = 1,
  kStep = 2,
  kDuration = 4,
  kOutputInterval = 8,
  kEveryOverride = 15,
};

/// Adds the positional scene file and the overrides named by `which` to `command`.
void add_scene_options(CLI::App& command, std::filesystem::path& scene, SceneOverrides& overrides,
                       unsigned which);

}  // namespace gp::cli
