#include "verification/srs/erratum_citations.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <regex>
#include <sstream>

namespace gp::verification {

std::vector<Citation> citations_in(const std::string& file, const std::string& text) {
  const std::regex id(R"((^|[^A-Za-z0-9_-])(E-[A-Z][A-Z0-9]+(?:-[A-Z0-9]+)*))");
  std::vector<Citation> found;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    for (std::sregex_iterator it(line.begin(), line.end(), id), end; it != end; ++it) {
      found.push_back({(*it)[2], file, number});
    }
  }
  return found;
}

std::vector<Citation> erratum_citations(const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  constexpr std::array extensions{".cpp", ".hpp", ".h", ".md", ".py", ".sh", ".mjs", ".txt"};
  std::vector<fs::path> files{root / "README.md", root / "srs" / "errata.md"};
  for (const char* dir : {"docs", "models", "src", "tests", "verification", "examples", "python"}) {
    if (!fs::is_directory(root / dir)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / dir)) {
      const auto ext = entry.path().extension().string();
      if (entry.is_regular_file() &&
          std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) {
        files.push_back(entry.path());
      }
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<Citation> citations;
  for (const auto& file : files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const auto found = citations_in(fs::relative(file, root).generic_string(), text.str());
    citations.insert(citations.end(), found.begin(), found.end());
  }
  return citations;
}

}  // namespace gp::verification
