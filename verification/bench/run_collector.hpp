#pragma once
// Google Benchmark's console output, keeping every measured run for the summary that follows it.

#include <benchmark/benchmark.h>

#include <vector>

namespace gp::bench {

class RunCollector : public benchmark::ConsoleReporter {
 public:
  /// Colours the console output only when `color` (e.g. when it is a terminal).
  explicit RunCollector(bool color) : ConsoleReporter(color ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& report) override;

  /// The runs that ended without error as they were displayed: the repetitions, the statistics
  /// computed from them (aggregates), or only the statistics under
  /// --benchmark_display_aggregates_only.
  const std::vector<Run>& runs() const { return runs_; }

 private:
  std::vector<Run> runs_;
};

}  // namespace gp::bench
