#include "verification/bench/summary.hpp"

#include <cstdint>
#include <cstdio>
#include <map>

#include "verification/bench/bench_engine.hpp"
#include "verification/bench/benchmarks.hpp"
#include "verification/bench/formatted.hpp"

namespace gp::bench {

std::vector<Figures> figures(const std::vector<Workload>& list,
                             const std::vector<benchmark::BenchmarkReporter::Run>& runs) {
  // Google Benchmark hands the display reporter either the repetitions or, with
  // --benchmark_display_aggregates_only, only the statistics computed from them.
  struct Measured {
    std::vector<double> ms;                   // per repetition
    std::map<std::string, double> statistic;  // "median", "min", "max", "stddev" [ms]
    std::int64_t repetitions = 0;
    double moved_m = -1.0;
    double heap_bytes = -1.0;
  };
  std::map<std::string, Measured> by_name;
  for (const auto& run : runs) {
    Measured& m = by_name[run.run_name.function_name];
    const double ms = run.GetAdjustedRealTime();  // in the benchmark's unit, ms
    if (run.run_type == benchmark::BenchmarkReporter::Run::RT_Aggregate) {
      m.statistic[run.aggregate_name] = ms;
      m.repetitions = run.repetitions;
    } else {
      m.ms.push_back(ms);
    }
    const bool typical = run.run_type != benchmark::BenchmarkReporter::Run::RT_Aggregate ||
                         run.aggregate_name == "median";
    if (!typical) continue;
    for (const auto& [name, value] :
         {std::pair{kMovedCounter, &m.moved_m}, std::pair{kHeapCounter, &m.heap_bytes}}) {
      if (const auto counter = run.counters.find(name); counter != run.counters.end()) {
        *value = counter->second;
      }
    }
  }
  std::vector<Figures> all;
  for (const Workload& w : list) {
    std::vector<std::string> labels;
    for (Engine engine : kEngines) labels.emplace_back(engine_label(engine));
    labels.emplace_back(kOursTwoThreads);
    for (const OursIntegrator& variant : kOursIntegrators) labels.emplace_back(variant.label);
    for (const std::string& label : labels) {
      const auto found = by_name.find(w.name + "/" + label);
      if (found == by_name.end()) continue;
      const Measured& m = found->second;
      Figures f = !m.ms.empty() ? figures_of(w, label, m.ms, m.moved_m)
                                : figures_of(w, label, static_cast<std::size_t>(m.repetitions),
                                             {m.statistic.at("median"), m.statistic.at("min"),
                                              m.statistic.at("max"), m.statistic.at("stddev")},
                                             m.moved_m);
      f.heap_bytes = m.heap_bytes;
      all.push_back(std::move(f));
    }
  }
  return all;
}

void print_summary(std::ostream& out, const std::vector<Figures>& all) {
  out << "\nSummary: wall time of one whole run [ms]; ours/engine = our median / the engine's "
         "(above 1: ours is slower; on the rows ours-2-threads, the speed-up of a second thread; "
         "on the rows ours-symplectic-euler and ours-rk4, the default integrator's time over "
         "that integrator's); "
         "heap the engine holds at the end of a run [KiB], and per body [B]\n";
  char line[200];
  std::snprintf(line, sizeof line, "%-20s %-21s %4s %10s %10s %10s %9s %11s %14s %10s %9s\n",
                "workload", "engine", "reps", "median", "min", "max", "stddev", "ours/engine",
                "body-steps/s", "heap", "heap/body");
  out << line;
  for (const Figures& f : all) {
    const auto ratio_value = ours_over_engine(all, f);
    const std::string ratio = ratio_value ? formatted("%.2f", *ratio_value) : "-";
    const bool measured = f.heap_bytes >= 0.0 && f.bodies > 0;
    const std::string heap = measured ? formatted("%.0f", f.heap_bytes / 1024) : "-";
    const std::string per_body =
        measured ? formatted("%.0f", f.heap_bytes / static_cast<double>(f.bodies)) : "-";
    std::snprintf(
        line, sizeof line, "%-20s %-21s %4zu %10.1f %10.1f %10.1f %9.1f %11s %14.3g %10s %9s\n",
        f.workload.c_str(), f.engine.c_str(), f.repetitions, f.median_ms, f.min_ms, f.max_ms,
        f.stddev_ms, ratio.c_str(), f.body_steps_per_s, heap.c_str(), per_body.c_str());
    out << line;
  }
  for (const Figures& f : all) {
    if (f.moved_m < 0.0) continue;
    out << f.workload << ": the watched (top) body moved " << formatted("%.4g", f.moved_m)
        << " m in " << f.engine << "\n";
  }
  const auto per_body = heap_per_added_body(all);
  if (!per_body.empty()) {
    out << "heap per disc added from rain1000 to rain4000 (held at the end of the run):";
    for (const auto& [engine, bytes] : per_body) {
      out << " " << engine << " " << formatted("%.0f", bytes) << " B";
    }
    out << "\n";
  }
  const auto growth = time_growth_over_bodies(all);
  if (!growth.empty()) {
    out << "time per step from rain1000, by medians and by the fastest runs, against N log N of "
           "the bodies:";
    const char* separator = " ";
    for (const TimeGrowth& g : growth) {
      out << separator << g.engine << " to " << g.workload << " " << formatted("%.2f", g.by_medians)
          << "x and " << formatted("%.2f", g.by_fastest) << "x (N log N "
          << formatted("%.2f", g.n_log_n) << "x)";
      separator = "; ";
    }
    out << "\n";
  }
}

}  // namespace gp::bench
