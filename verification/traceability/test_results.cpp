#include "verification/traceability/test_results.hpp"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace gp::verification {

namespace {

// The five entities of XML; Catch2 writes test names with &apos; and &quot;.
std::string unescape(const std::string& text) {
  static const std::pair<const char*, const char*> kEntities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  std::string out = text;
  for (const auto& [entity, character] : kEntities) {
    for (auto at = out.find(entity); at != std::string::npos; at = out.find(entity, at + 1)) {
      out.replace(at, std::string(entity).size(), character);
    }
  }
  return out;
}

}  // namespace

TestResults load_test_results(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read test results " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  TestResults results;
  const std::regex name(R"re(<testcase\b[^>]*?\bname="([^"]*)"[^>]*?(/?)>)re");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), name); it != std::sregex_iterator();
       ++it) {
    const std::string test = unescape((*it)[1].str());
    bool passed = true;
    if ((*it)[2].length() == 0) {  // not self-closing: look inside up to </testcase>
      const auto body = static_cast<std::size_t>(it->position() + it->length());
      const auto end = xml.find("</testcase>", body);
      const std::string inside = xml.substr(body, end - body);
      passed = inside.find("<failure") == std::string::npos &&
               inside.find("<error") == std::string::npos;
    }
    const auto [entry, added] = results.emplace(test, passed);
    if (!added) entry->second = entry->second && passed;
  }
  if (results.empty()) throw std::runtime_error("no test case in " + file.string());
  return results;
}

std::optional<bool> result_of(const TestResults& results, const std::string& name) {
  std::optional<bool> passed;
  for (auto it = results.lower_bound(name);
       it != results.end() && it->first.compare(0, name.size(), name) == 0; ++it) {
    if (it->first.size() == name.size() || it->first[name.size()] == '/') {
      passed = passed.value_or(true) && it->second;
    }
  }
  return passed;
}

}  // namespace gp::verification
