// Criteria at the measured level: a limit more than 10× above what it bounds would let a
// regression of that size pass, so it either comes down or says why it cannot.
#include "verification/suite/suite.hpp"

namespace gp::verification {

std::vector<Check> criteria_level_checks(const std::vector<Check>& checks, const SuiteOptions& o) {
  CheckList list("criteria at the measured level");
  std::size_t with_limits = 0;
  std::size_t with_reason = 0;
  for (const Check& c : checks) {
    if (c.limits.empty()) continue;
    ++with_limits;
    if (!c.looser_because.empty()) ++with_reason;
  }
  std::string measured = std::to_string(with_limits) + " rows with numeric limits, " +
                         std::to_string(with_reason) + " of them with a reason to be looser";
  const std::vector<const Check*> loose = loose_rows(checks);
  if (!loose.empty()) measured += "; looser than 10× without a reason:";
  for (const Check* c : loose) measured += " " + c->section + ": " + c->name + ";";
  const std::string criterion =
      "every limit within 10× of its figure, or a one-line reason beside it";
  const std::string name = "every row checked by a numeric limit";
  if (o.quick) {
    list.report(name + " (judged in the full run only: the quick runs are shorter)", "",
                measured + "; the full run's criterion: " + criterion);
  } else {
    list.check(name, "", measured, criterion, loose.empty());
  }
  return list.rows();
}

}  // namespace gp::verification
