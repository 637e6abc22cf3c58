// The fuzzer's seed corpus and every crash input kept, replayed through its entry point with
// the ordinary build (so also under coverage and the gcc sanitizers): each ends as the prefix of
// its file name says, "ran", "input_error" or "numerical_error" (verification/fuzz/README.md).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "verification/fuzz/scene_input.hpp"

namespace {
namespace test_fuzz_inputs {

const std::filesystem::path kFuzz = std::filesystem::path(GP_SOURCE_DIR) / "verification" / "fuzz";

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Replays every file of `folder` and checks its outcome against its name; returns the count.
int replay(const std::filesystem::path& folder) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().filename() == "README.md") continue;
    const std::string name = entry.path().filename().string();
    INFO(entry.path().string());
    const std::string expected = name.substr(0, name.find('-'));
    CHECK(gp::fuzz::outcome_name(gp::fuzz::run_scene_input(contents(entry.path()))) == expected);
    ++count;
  }
  return count;
}

TEST_CASE("Every seed of the fuzz corpus ends in the outcome its name gives",
          "[FR:Verify-Physical_Constraints]") {
  // The 64 bad inputs of test_scene_errors.cpp and the two of the command-line tests.
  CHECK(replay(kFuzz / "corpus") >= 66);
}

TEST_CASE("Every kept crash input now ends in a typed outcome",
          "[FR:Verify-Physical_Constraints]") {
  // Seven so far (verification/fuzz/README.md); none may go missing.
  CHECK(replay(kFuzz / "crashes") >= 7);
}

TEST_CASE("Every shipped scene loads and runs within the fuzzer's bounds",
          "[FR:Input-Initial-Conditions]") {
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(GP_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path().string());
    CHECK(gp::fuzz::run_scene_input(contents(entry.path())) == gp::fuzz::SceneInputOutcome::kRan);
  }
}

}  // namespace test_fuzz_inputs
}  // namespace
