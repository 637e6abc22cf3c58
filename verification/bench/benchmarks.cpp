#include "verification/bench/benchmarks.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <exception>
#include <memory>
#include <string>
#include <string_view>

#include "verification/bench/bench_engine.hpp"
#include "verification/bench/timed_run.hpp"

namespace gp::bench {

namespace {

void run_workload(benchmark::State& state, const Workload& w, Engine engine, int threads) {
  double moved = 0.0;
  double heap = 0.0;
  try {
    // The CPU column, like the manual time, counts the steps alone: the timer is paused over
    // building and destroying the scene.
    const AroundSteps around{[&state] { state.ResumeTiming(); }, [&state] { state.PauseTiming(); }};
    for (auto _ : state) {
      state.PauseTiming();
      const TimedRun run = time_run(w, engine, around, threads);
      state.ResumeTiming();
      state.SetIterationTime(run.seconds);
      moved = run.moved_m;
      heap = run.heap_bytes;
    }
  } catch (const std::exception& e) {  // NumericalError: a state became non-finite
    state.SkipWithError(e.what());
    return;
  }
  const auto body_steps = static_cast<double>(w.scene.bodies.size()) * w.steps;
  state.counters[kBodyStepsCounter] =
      benchmark::Counter(body_steps, benchmark::Counter::kIsIterationInvariantRate);
  if (w.watched) state.counters[kMovedCounter] = moved;
  state.counters[kHeapCounter] = heap;
}

double smallest(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}
double largest(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end());
}

// The benchmarks share their workload, so that a variant made here outlives the call without a
// copy of the scene per engine.
void add(std::shared_ptr<const Workload> w, Engine engine, std::string_view label, int threads) {
  const std::string name = w->name + "/" + std::string(label);
  benchmark::RegisterBenchmark(name.c_str(),
                               [w = std::move(w), engine, threads](benchmark::State& s) {
                                 run_workload(s, *w, engine, threads);
                               })
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond)
      ->ComputeStatistics("min", smallest)
      ->ComputeStatistics("max", largest);
}

}  // namespace

void register_benchmarks(const std::vector<Workload>& list) {
  for (const Workload& w : list) {
    const auto shared = std::make_shared<const Workload>(w);
    for (Engine engine : kEngines) add(shared, engine, engine_label(engine), 1);
    add(shared, Engine::Ours, kOursTwoThreads, 2);
    for (const OursIntegrator& variant : kOursIntegrators) {
      auto with = std::make_shared<Workload>(w);
      with->scene.settings.integrator = variant.integrator;
      add(std::move(with), Engine::Ours, variant.label, 1);
    }
  }
}

}  // namespace gp::bench
