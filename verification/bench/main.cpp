// build/bin/gamephysics_bench: ours, Chipmunk2D and Box2D on the same workloads in one run
// (NFR:Performance), then a summary with medians, spreads and ratios.
//
//   gamephysics_bench [--quick] [Google Benchmark flags]
//
// By default each benchmark is repeated 5 times and the repetitions of all benchmarks run in
// random interleaved order, so that slow phases of the machine hit every engine alike; --quick
// runs each once and leaves out rain16000. Flags given on the command line override these. Before
// and after the benchmarks, what the machine's second core gives then (core_capacity.hpp) and how
// long a cache line takes to go from one core to the other and back (core_hand_over.hpp).

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "verification/bench/bench_engine.hpp"
#include "verification/bench/benchmarks.hpp"
#include "verification/bench/core_capacity.hpp"
#include "verification/bench/core_hand_over.hpp"
#include "verification/bench/run_collector.hpp"
#include "verification/bench/summary.hpp"
#include "verification/bench/workloads.hpp"

int main(int argc, char** argv) {
  bool quick = false;
  std::vector<char*> args{argv[0]};
  std::string repetitions = "--benchmark_repetitions=5";
  std::string interleave = "--benchmark_enable_random_interleaving=true";
  std::string aggregates = "--benchmark_display_aggregates_only=true";
  args.push_back(repetitions.data());
  args.push_back(interleave.data());
  args.push_back(aggregates.data());
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
      repetitions = "--benchmark_repetitions=1";
    } else {
      args.push_back(argv[i]);  // later flags override the defaults above
    }
  }
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 2;

  const std::vector<gp::bench::Workload> workloads =
      gp::bench::workloads(std::string(GP_SOURCE_DIR) + "/scenes", GP_BENCH_SCENES, quick);
  gp::bench::register_benchmarks(workloads);
  // Described before printing, so that Chipmunk's banner on its first space comes first.
  const std::vector<std::string> engines = gp::bench::engine_settings(workloads.front().scene);
  std::cout << "Engines, on every workload:\n";
  for (const std::string& engine : engines) std::cout << "  " << engine << "\n";
  std::cout.flush();

  // The second core's worth before and after, beside which to read the two-thread rows.
  const gp::bench::Workload& reference = *std::find_if(
      workloads.begin(), workloads.end(), [](const auto& w) { return w.name == "pyramid20"; });
  constexpr int kCapacityRounds = 5;
  constexpr int kHandOverTrips = 100000;  // 50 ms a round at the 500 ns seen on these machines
  const auto capacity = [&](const char* moment) {
    return gp::bench::describe(moment, reference,
                               gp::bench::measure_core_capacity(reference, kCapacityRounds));
  };
  const auto hand_over = [](const char* moment) {
    return gp::bench::describe(moment,
                               gp::bench::measure_hand_over(kCapacityRounds, kHandOverTrips));
  };
  const std::string at_start =
      capacity("at the start of the run") + "\n" + hand_over("at the start of the run");
  std::cout << at_start << "\n";
  std::cout.flush();

  gp::bench::RunCollector collector(::isatty(STDOUT_FILENO) != 0);
  benchmark::RunSpecifiedBenchmarks(&collector);
  gp::bench::print_summary(std::cout, gp::bench::figures(workloads, collector.runs()));
  std::cout << at_start << "\n"
            << capacity("at the end of the run") << "\n"
            << hand_over("at the end of the run") << "\n";
  benchmark::Shutdown();
  return 0;
}
