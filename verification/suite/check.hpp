#pragma once
// One row of the verification report: what was checked, against which criterion, with which
// result, and which SRS items it verifies.

#include <string>
#include <vector>

namespace gp::verification {

struct Check {
  std::string section;    ///< e.g. "accuracy against the oracle"
  std::string name;       ///< e.g. "bouncing_ball, velocity_verlet, dt = 1/60 s"
  std::string srs_ids;    ///< e.g. "IM:col2D GD:impulse"
  std::string measured;   ///< the figures, as text
  std::string criterion;  ///< the pass criterion, or "reported" when none
  bool passed = true;
};

/// Rows of a section, added with a criterion or as plain figures.
class CheckList {
 public:
  explicit CheckList(std::string section) : section_(std::move(section)) {}

  void check(std::string name, std::string srs_ids, std::string measured, std::string criterion,
             bool passed) {
    rows_.push_back({section_, std::move(name), std::move(srs_ids), std::move(measured),
                     std::move(criterion), passed});
  }
  void report(std::string name, std::string srs_ids, std::string measured) {
    check(std::move(name), std::move(srs_ids), std::move(measured), "reported", true);
  }
  const std::vector<Check>& rows() const { return rows_; }

 private:
  std::string section_;
  std::vector<Check> rows_;
};

/// A number as the report prints it: 3 significant digits, e.g. "1.23e-10".
std::string figure(double value);

}  // namespace gp::verification
