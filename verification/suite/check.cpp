#include "verification/suite/check.hpp"

namespace gp::verification {

std::vector<const Check*> loose_rows(const std::vector<Check>& checks) {
  std::vector<const Check*> loose;
  for (const Check& c : checks) {
    if (!c.looser_because.empty()) continue;
    for (const Limit& l : c.limits) {
      if (l.limit > kLooseness * l.measured) {
        loose.push_back(&c);
        break;
      }
    }
  }
  return loose;
}

}  // namespace gp::verification
