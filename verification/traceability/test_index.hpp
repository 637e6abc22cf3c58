#pragma once
// The Catch2 test cases of tests/, with the SRS ids they are tagged with and the text of their
// bodies, in which the traceability check looks for calls of the model functions.

#include <filesystem>
#include <string>
#include <vector>

namespace gp::verification {

struct TestCase {
  std::string name;               ///< as given to TEST_CASE
  std::string file;               ///< relative to the repository root
  std::vector<std::string> tags;  ///< e.g. "DD:ctrOfMass"
  std::string body;               ///< the source between the braces of the test case
};

/// The text between the brace at or after `open` and its matching brace, skipping braces in
/// comments and in string and character literals (raw strings included); to the end of `source`
/// when unmatched.
std::string braced_body(const std::string& source, std::size_t open);

/// Every TEST_CASE("name", "[tag]...") under `tests_dir`, sorted by file then position; files are
/// named relative to `root`.
std::vector<TestCase> index_tests(const std::filesystem::path& root,
                                  const std::filesystem::path& tests_dir);

}  // namespace gp::verification
