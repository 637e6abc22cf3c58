#pragma once
// Writing the verification report.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "verification/suite/speed_table.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

struct SectionSummary {
  int rows = 0;
  int checked = 0;
  int failed = 0;
};

struct ReportSummary {
  std::map<std::string, SectionSummary> sections;
  std::vector<const Check*> failures;
};

ReportSummary summarise(const std::vector<Check>& checks);

/// Writes report.md, index.html and data/*.csv into `out`, linking the `plots` (PNG names), with
/// the section `speed` after the checks and its table in speed.json (removed when it has none, so
/// that no older table passes for this run's).
void write_report(const std::filesystem::path& out, const std::vector<Check>& checks,
                  const CsvFiles& data, const std::vector<std::string>& plots,
                  const SpeedSection& speed);

/// Runs `script` (plots.py) on the data in `out`; returns the PNG files it made, none when
/// matplotlib is missing (its message is in out/plots.log).
std::vector<std::string> make_plots(const std::filesystem::path& script,
                                    const std::filesystem::path& out);

}  // namespace gp::verification
