#include <algorithm>

#include "verification/suite/suite.hpp"

namespace gp::verification {

std::vector<NamedScene> load_scenes(const std::filesystem::path& directory) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<NamedScene> scenes;
  for (const auto& file : files) scenes.push_back({file.stem().string(), load_scene(file)});
  return scenes;
}

}  // namespace gp::verification
