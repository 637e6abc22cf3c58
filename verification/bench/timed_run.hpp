#pragma once
// One whole run of a workload in one engine, timed alike for Google Benchmark
// (gamephysics_bench) and for the speed section of `gamephysics verify`.

#include <functional>

#include "verification/bench/bench_engine.hpp"
#include "verification/bench/workloads.hpp"

namespace gp::bench {

struct TimedRun {
  /// Wall-clock time of the `steps` steps; building and destroying the scene are left out, as
  /// they are not what a game pays per frame.
  double seconds = 0.0;
  double moved_m = -1.0;  ///< the watched body's displacement; negative when none is watched
  /// Bytes of heap the engine holds at the end of the run, scene and all (glibc's count of the
  /// heap in use, after less before setting the scene up).
  double heap_bytes = 0.0;
};

/// Called just before the first step and just after the last, so that a caller's own clocks
/// (Google Benchmark's CPU time) can leave the set-up out too.
struct AroundSteps {
  std::function<void()> before;
  std::function<void()> after;
};

/// Sets `w` up in `engine`, steps it `w.steps` times by w.scene.dt, times the steps and measures
/// the heap the engine then holds. Ours runs on `threads` threads (the peers on one). Throws what
/// the engine throws (NumericalError when a state becomes non-finite).
TimedRun time_run(const Workload& w, Engine engine, const AroundSteps& around = {},
                  int threads = 1);

}  // namespace gp::bench
