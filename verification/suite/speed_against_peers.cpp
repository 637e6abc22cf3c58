// Speed against the peers (NFR:Performance): the headline benchmark workloads timed in ours,
// Chipmunk2D and Box2D within `gamephysics verify`, so that its report carries the figures that
// README quotes.
#include <array>
#include <chrono>
#include <ctime>
#include <exception>

#include "verification/bench/bench_engine.hpp"
#include "verification/bench/timed_run.hpp"
#include "verification/suite/speed_table.hpp"

namespace gp::verification {

namespace {

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// Runs each engine in turn, once per repetition, rather than all repetitions of one engine
// together: a phase of the machine slowed by other jobs then hits every engine alike.
std::vector<bench::Figures> time_alternately(const bench::Workload& w, int repetitions) {
  std::array<std::vector<double>, bench::kEngines.size()> ms;
  std::array<double, bench::kEngines.size()> moved{};
  for (int r = 0; r < repetitions; ++r) {
    for (std::size_t e = 0; e < bench::kEngines.size(); ++e) {
      const bench::TimedRun run = bench::time_run(w, bench::kEngines[e]);
      ms[e].push_back(run.seconds * 1e3);
      moved[e] = run.moved_m;
    }
  }
  std::vector<bench::Figures> all;
  for (std::size_t e = 0; e < bench::kEngines.size(); ++e) {
    all.push_back(bench::figures_of(w, std::string(bench::engine_label(bench::kEngines[e])), ms[e],
                                    moved[e]));
  }
  return all;
}

}  // namespace

SpeedSection speed_against_peers(const SuiteOptions& o) {
  if (o.quick) {
    return {std::nullopt,
            "skipped: --quick leaves it out; `build/bin/gamephysics verify` without --quick "
            "measures it"};
  }
  const auto begin = std::chrono::steady_clock::now();
  SpeedTable table;
  table.measured_at = utc_now();
  table.repetitions = o.speed_repetitions;
  try {
    const std::vector<bench::Workload> list = bench::headline_workloads(o.root / "scenes");
    table.engines = bench::engine_settings(list.front().scene);
    for (const bench::Workload& w : list) {
      if (o.progress) *o.progress << "  speed against the peers: " << w.name << "\n";
      const auto figures = time_alternately(w, o.speed_repetitions);
      table.figures.insert(table.figures.end(), figures.begin(), figures.end());
    }
  } catch (const std::exception& e) {  // NumericalError in an engine, or a scene that won't load
    return {std::nullopt, std::string("not measured: ") + e.what()};
  }
  table.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return {std::move(table), ""};
}

}  // namespace gp::verification
