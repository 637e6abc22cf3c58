#include "verification/srs/errata.hpp"

#include <fstream>
#include <regex>
#include <stdexcept>

namespace gp::verification {

namespace {

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t") - begin + 1);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  for (char c : text) {
    if (c == separator) {
      if (!trim(part).empty()) parts.push_back(trim(part));
      part.clear();
    } else {
      part += c;
    }
  }
  if (!trim(part).empty()) parts.push_back(trim(part));
  return parts;
}

}  // namespace

std::vector<Erratum> load_errata(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open the errata");
  const std::regex heading(R"(^### (E-[A-Z0-9-]+): (.+)$)");
  const std::regex field(R"(^- \*\*(Items|Kind|Edges|Shown by):\*\* (.*)$)");
  // Test names are quoted in "Shown by" because they may contain commas.
  const std::regex quoted("\"([^\"]+)\"");
  std::vector<Erratum> errata;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::smatch match;
    if (std::regex_match(line, match, heading)) {
      errata.push_back({match[1], match[2], {}, {}, {}, {}});
    } else if (std::regex_match(line, match, field)) {
      if (errata.empty()) {
        throw std::runtime_error(file.string() + ":" + std::to_string(number) +
                                 ": field outside an erratum");
      }
      Erratum& e = errata.back();
      const std::string name = match[1], value = match[2];
      if (name == "Items") {
        e.items = split(value, ',');
      } else if (name == "Kind") {
        e.kind = trim(value);
      } else if (name == "Edges") {
        for (const auto& edge : split(value, ';')) {
          const auto arrow = edge.find("->");
          if (arrow == std::string::npos) {
            throw std::runtime_error(file.string() + ":" + std::to_string(number) +
                                     ": an edge must read 'FROM -> TO', got '" + edge + "'");
          }
          e.edges.emplace_back(trim(edge.substr(0, arrow)), trim(edge.substr(arrow + 2)));
        }
      } else {
        for (std::sregex_iterator it(value.begin(), value.end(), quoted), end; it != end; ++it) {
          e.tests.push_back((*it)[1]);
        }
      }
    }
  }
  return errata;
}

}  // namespace gp::verification
