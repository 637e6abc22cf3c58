#include "verification/traceability/test_index.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

namespace gp::verification {

std::vector<TestCase> index_tests(const std::filesystem::path& root,
                                  const std::filesystem::path& tests_dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(tests_dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".cpp") files.push_back(entry);
  }
  std::sort(files.begin(), files.end());
  const std::regex test_case(R"re(TEST_CASE\(\s*"((?:[^"\\]|\\.)*)"\s*,\s*"([^"]*)"\s*\))re");
  const std::regex tag(R"(\[([^\]]+)\])");
  std::vector<TestCase> tests;
  for (const auto& file : files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const std::string source = text.str();
    for (std::sregex_iterator it(source.begin(), source.end(), test_case), end; it != end; ++it) {
      TestCase test{(*it)[1], std::filesystem::relative(file, root).generic_string(), {}};
      const std::string tags = (*it)[2];
      for (std::sregex_iterator t(tags.begin(), tags.end(), tag); t != end; ++t) {
        test.tags.push_back((*t)[1]);
      }
      tests.push_back(std::move(test));
    }
  }
  return tests;
}

}  // namespace gp::verification
