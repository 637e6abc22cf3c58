#include "verification/bench/run_collector.hpp"

namespace gp::bench {

void RunCollector::ReportRuns(const std::vector<Run>& report) {
  ConsoleReporter::ReportRuns(report);
  for (const Run& run : report) {
    if (!run.error_occurred) runs_.push_back(run);
  }
}

}  // namespace gp::bench
