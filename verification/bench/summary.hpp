#pragma once
// The summary printed after the benchmarks: per workload and engine the median, the spread and
// the ratio of our time to the engine's, the free-fall throughput and the pyramid's stability.

#include <benchmark/benchmark.h>

#include <ostream>
#include <string>
#include <vector>

#include "verification/bench/workloads.hpp"

namespace gp::bench {

/// Median, min, max and sample standard deviation of the wall time [ms] of one workload in one
/// engine, the body-steps per second of the median run and the watched body's displacement [m].
struct Figures {
  std::string workload;
  std::string engine;
  std::size_t repetitions = 0;
  double median_ms = 0.0, min_ms = 0.0, max_ms = 0.0, stddev_ms = 0.0;
  double body_steps_per_s = 0.0;
  double moved_m = -1.0;  ///< negative when the workload watches no body
};

/// The figures of every "<workload>/<engine>" that has runs, in the order of `list` and of the
/// engines: from its repetitions, or from the statistics "median", "min", "max" and "stddev"
/// when only those are in `runs`.
std::vector<Figures> figures(const std::vector<Workload>& list,
                             const std::vector<benchmark::BenchmarkReporter::Run>& runs);

/// Writes the table of `all`, with ours/engine = our median over the engine's, the body-steps per
/// second of free10000 and the displacement of every watched body.
void print_summary(std::ostream& out, const std::vector<Figures>& all);

}  // namespace gp::bench
