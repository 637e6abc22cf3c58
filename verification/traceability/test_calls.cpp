#include "verification/traceability/test_calls.hpp"

#include <regex>

namespace gp::verification {

std::set<std::string> models_called(const std::string& body,
                                    const std::vector<models::Registration>& registrations) {
  std::set<std::string> called;
  std::vector<const models::Registration*> pending;
  for (const auto& r : registrations) {
    // "gp::dd::torque" is called as dd::torque( or dd::torque<...>(.
    const std::string name = r.function.substr(r.function.find("::") + 2);
    // The call contains the name: most bodies do not, and need no regex (it was 40 % of `trace`).
    if (body.find(name) == std::string::npos) continue;
    const std::regex call("\\b" + std::regex_replace(name, std::regex(":"), "\\:") +
                          "\\s*(<[^;(){}]*>)?\\s*\\(");
    if (std::regex_search(body, call) && called.insert(r.id).second) pending.push_back(&r);
  }
  while (!pending.empty()) {
    const auto* r = pending.back();
    pending.pop_back();
    for (const auto& used : r->uses) {
      if (!called.insert(used).second) continue;
      for (const auto& other : registrations) {
        if (other.id == used) pending.push_back(&other);
      }
    }
  }
  return called;
}

}  // namespace gp::verification
