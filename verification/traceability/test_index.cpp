#include "verification/traceability/test_index.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

namespace gp::verification {

std::string braced_body(const std::string& source, std::size_t open) {
  const std::size_t begin = source.find('{', open);
  if (begin == std::string::npos) return "";
  int depth = 0;
  for (std::size_t i = begin; i < source.size(); ++i) {
    const char c = source[i];
    const auto next = i + 1 < source.size() ? source[i + 1] : '\0';
    if (c == '/' && next == '/') {
      i = std::min(source.find('\n', i), source.size());
    } else if (c == '/' && next == '*') {
      i = std::min(source.find("*/", i + 2), source.size()) + 1;
    } else if (c == 'R' && next == '"') {
      const auto paren = source.find('(', i + 2);
      const std::string close = std::string(")") + source.substr(i + 2, paren - i - 2) + "\"";
      i = std::min(source.find(close, paren), source.size()) + close.size() - 1;
    } else if (c == '"' || c == '\'') {
      for (++i; i < source.size() && source[i] != c; ++i) i += source[i] == '\\' ? 1 : 0;
    } else if (c == '{') {
      ++depth;
    } else if (c == '}' && --depth == 0) {
      return source.substr(begin + 1, i - begin - 1);
    }
  }
  return source.substr(begin + 1);
}

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
      const auto end_of_match = static_cast<std::size_t>(it->position() + it->length());
      TestCase test{(*it)[1],
                    std::filesystem::relative(file, root).generic_string(),
                    {},
                    braced_body(source, end_of_match)};
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
