#include "verification/traceability/code_edges.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace gp::verification {

std::map<std::string, std::vector<std::string>> called_models(
    const std::filesystem::path& root, const std::vector<models::Registration>& registrations) {
  std::map<std::string, std::string> id_of_function;
  for (const auto& r : registrations) id_of_function[r.function] = r.id;
  const std::regex call(R"(\b(tm|gd|dd|im)::(\w+)\s*(?:<[^;(){}]*>)?\s*\()");
  std::map<std::string, std::vector<std::string>> calls;
  for (const auto& r : registrations) {
    std::ifstream in(root / r.file);
    std::stringstream text;
    text << in.rdbuf();
    const std::string source = text.str();
    std::set<std::string> used;
    for (std::sregex_iterator it(source.begin(), source.end(), call), end; it != end; ++it) {
      const auto found = id_of_function.find("gp::" + (*it)[1].str() + "::" + (*it)[2].str());
      if (found != id_of_function.end() && found->second != r.id) used.insert(found->second);
    }
    calls[r.id] = {used.begin(), used.end()};
  }
  return calls;
}

}  // namespace gp::verification
