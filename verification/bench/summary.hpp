#pragma once
// The summary printed after the benchmarks: per workload and engine the median, the spread and
// the ratio of our time to the engine's, the free-fall throughput and the pyramid's stability.

#include <benchmark/benchmark.h>

#include <ostream>
#include <vector>

#include "verification/bench/figures.hpp"
#include "verification/bench/workloads.hpp"

namespace gp::bench {

/// The figures of every "<workload>/<engine>" that has runs, in the order of `list` and of the
/// engines: from its repetitions, or from the statistics "median", "min", "max" and "stddev"
/// when only those are in `runs`.
std::vector<Figures> figures(const std::vector<Workload>& list,
                             const std::vector<benchmark::BenchmarkReporter::Run>& runs);

/// Writes the table of `all`, with ours/engine = our median over the engine's, the body-steps per
/// second of free10000 and the displacement of every watched body.
void print_summary(std::ostream& out, const std::vector<Figures>& all);

}  // namespace gp::bench
