#pragma once
// Scene files for the tests: JSON text written to a temporary file, removed afterwards.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "engine/scene/scene_space.hpp"
#include "scene/input_error.hpp"
#include "scene/scene.hpp"

namespace gp::test {

class SceneFile {
 public:
  explicit SceneFile(const std::string& json) : path_(fresh_path()) {
    std::ofstream(path_) << json;
  }
  ~SceneFile() { std::filesystem::remove(path_); }
  SceneFile(const SceneFile&) = delete;
  SceneFile& operator=(const SceneFile&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  // ctest runs test cases in parallel processes: the pid keeps their files apart.
  static std::filesystem::path fresh_path() {
    static int count = 0;
    return std::filesystem::temp_directory_path() /
           ("gp_scene_" + std::to_string(getpid()) + "_" + std::to_string(count++) + ".json");
  }

  std::filesystem::path path_;
};

/// The scene in `json`, loaded.
inline Scene load(const std::string& json, const SceneOverrides& overrides = {}) {
  const SceneFile file(json);
  return load_scene(file.path(), overrides);
}

/// The InputError that loading `json` and building its space throws, if any.
inline std::optional<InputError> input_error(const std::string& json,
                                             const SceneOverrides& overrides = {}) {
  try {
    build_space(load(json, overrides));
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

/// A scene with one step setting and `bodies` (the inside of the bodies array).
inline std::string scene_with(const std::string& bodies) {
  return R"({"dt": 0.01, "duration": 1, "bodies": [)" + bodies + "]}";
}

}  // namespace gp::test
