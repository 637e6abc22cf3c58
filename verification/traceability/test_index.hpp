#pragma once
// The Catch2 test cases of tests/, with the SRS ids they are tagged with.

#include <filesystem>
#include <string>
#include <vector>

namespace gp::verification {

struct TestCase {
  std::string name;               ///< as given to TEST_CASE
  std::string file;               ///< relative to the repository root
  std::vector<std::string> tags;  ///< e.g. "DD:ctrOfMass"
};

/// Every TEST_CASE("name", "[tag]...") under `tests_dir`, sorted by file then position; files are
/// named relative to `root`.
std::vector<TestCase> index_tests(const std::filesystem::path& root,
                                  const std::filesystem::path& tests_dir);

}  // namespace gp::verification
