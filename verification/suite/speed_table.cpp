#include "verification/suite/speed_table.hpp"

#include <map>

#include "verification/bench/bench_engine.hpp"
#include "verification/bench/formatted.hpp"

namespace gp::verification {

std::string speed_target(const std::string& workload) {
  // The targets of the issue on NFR:Performance; the other workloads have none.
  static const std::map<std::string, std::string> targets{
      {"free10000", "≥ 3e7 body-steps/s"},
      {"rain1000", "ours/peer < 1"},
      {"pyramid20", "ours/peer < 1; top box moves < 3 cm"},
  };
  const auto found = targets.find(workload);
  return found == targets.end() ? std::string() : found->second;
}

std::vector<std::vector<std::string>> speed_cells(const SpeedTable& table) {
  std::vector<std::vector<std::string>> cells{
      {"workload", "engine", "precision, build", "runs", "median [ms]", "min [ms]", "max [ms]",
       "ours/engine", "below 1", "body-steps/s", "watched body moved", "target (issue)"}};
  std::string workload;
  for (const bench::Figures& f : table.figures) {
    const bool first = f.workload != workload;
    workload = f.workload;
    const bool peer = f.engine != bench::engine_label(bench::Engine::Ours);
    const auto ratio = bench::ours_over_engine(table.figures, f);
    const bool compared = peer && ratio.has_value();
    cells.push_back({first ? f.workload : "", f.engine, std::string(bench::engine_build(f.engine)),
                     std::to_string(f.repetitions), bench::formatted("%.1f", f.median_ms),
                     bench::formatted("%.1f", f.min_ms), bench::formatted("%.1f", f.max_ms),
                     compared ? bench::formatted("%.2f", *ratio) : "",
                     compared ? (*ratio < 1.0 ? "yes" : "no") : "", figure(f.body_steps_per_s),
                     f.moved_m < 0.0 ? "" : figure(f.moved_m * 1e3) + " mm",
                     first ? speed_target(f.workload) : ""});
  }
  return cells;
}

}  // namespace gp::verification
