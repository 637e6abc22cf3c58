#pragma once
// The section "speed against the peers" of `gamephysics verify`: the benchmark workloads of
// NFR:Performance timed in ours, Chipmunk2D and Box2D. A measurement, not a check: it has no
// criterion, and states the targets of the issue beside the figures.

#include <optional>
#include <string>
#include <vector>

#include "verification/bench/figures.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

struct SpeedTable {
  std::vector<bench::Figures> figures;  ///< per workload: ours, then the peers
  std::vector<std::string> engines;     ///< each engine with its settings
  int repetitions = 0;                  ///< runs of each workload in each engine
  double seconds = 0.0;                 ///< wall time of the whole section
  std::string measured_at;              ///< UTC, ISO 8601
};

/// The table, or why there is none (skipped by --quick, or a run failed).
struct SpeedSection {
  std::optional<SpeedTable> table;
  std::string why_not;
};

/// The target for `workload`, empty when it names none.
std::string speed_target(const std::string& workload);

/// The table as text, the header first: per workload and engine its precision and build, the runs,
/// the median, min and max wall time [ms], on the peers' rows ours/engine and whether it is below
/// 1, body-steps per second, the watched body's displacement and, on the first row of a workload,
/// its target.
std::vector<std::vector<std::string>> speed_cells(const SpeedTable& table);

/// Times every headline workload (bench::headline_workloads) o.speed_repetitions times in each
/// engine, alternately (ours, chipmunk, box2d, ours, …) so that a slow phase of the machine hits
/// all alike. Skipped under o.quick.
SpeedSection speed_against_peers(const SuiteOptions& o);

}  // namespace gp::verification
