#pragma once
// One row of the verification report: what was checked, against which criterion, with which
// result, and which SRS items it verifies.

#include <string>
#include <vector>

namespace gp::verification {

/// A measured figure and the limit it must not exceed, in the same unit.
struct Limit {
  double measured;
  double limit;
};

struct Check {
  std::string section;    ///< e.g. "accuracy against the oracle"
  std::string name;       ///< e.g. "bouncing_ball, velocity_verlet, dt = 1/60 s"
  std::string srs_ids;    ///< e.g. "IM:col2D GD:impulse"
  std::string measured;   ///< the figures, as text
  std::string criterion;  ///< the pass criterion, or "reported" when none
  bool passed = true;
  /// The figures of a row checked by CheckList::within, each with its limit.
  std::vector<Limit> limits;
  /// Why a limit may sit more than 10× above its figure; empty when none does.
  std::string looser_because;
};

/// The most a limit may exceed its figure without a stated reason.
inline constexpr double kLooseness = 10.0;

/// Rows of a section, added with a criterion or as plain figures.
class CheckList {
 public:
  explicit CheckList(std::string section) : section_(std::move(section)) {}

  void check(std::string name, std::string srs_ids, std::string measured, std::string criterion,
             bool passed) {
    rows_.push_back({section_,
                     std::move(name),
                     std::move(srs_ids),
                     std::move(measured),
                     std::move(criterion),
                     passed,
                     {},
                     {}});
  }
  /// A row that passes when every figure is within its limit. A limit more than kLooseness times
  /// its figure needs `looser_because` (one line), which the report shows beside the criterion,
  /// marked "looser than 10×" when a limit is; loose_rows() finds the rows without one.
  void within(std::string name, std::string srs_ids, std::string measured, std::string criterion,
              std::vector<Limit> limits, std::string looser_because = "") {
    bool passed = true;
    bool loose = false;
    for (const Limit& l : limits) {
      passed = passed && l.measured <= l.limit;
      loose = loose || l.limit > kLooseness * l.measured;
    }
    if (!looser_because.empty()) {
      criterion += (loose ? " (looser than 10×: " : " (") + looser_because + ")";
    }
    rows_.push_back({section_, std::move(name), std::move(srs_ids), std::move(measured),
                     std::move(criterion), passed, std::move(limits), std::move(looser_because)});
  }
  void report(std::string name, std::string srs_ids, std::string measured) {
    check(std::move(name), std::move(srs_ids), std::move(measured), "reported", true);
  }
  const std::vector<Check>& rows() const { return rows_; }

 private:
  std::string section_;
  std::vector<Check> rows_;
};

/// The rows checked by CheckList::within with a limit more than kLooseness times its figure (a
/// figure of 0 counts as below any limit) and no reason why.
std::vector<const Check*> loose_rows(const std::vector<Check>& checks);

/// A number as the report prints it: 3 significant digits, e.g. "1.23e-10".
std::string figure(double value);

}  // namespace gp::verification
