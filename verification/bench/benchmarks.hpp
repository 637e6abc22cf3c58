#pragma once
// Google Benchmark registration of every workload in every engine: one benchmark iteration is one
// whole run, timed by time_run (timed_run.hpp) without the set-up and tear-down of the scene.

#include <vector>

#include "verification/bench/workloads.hpp"

namespace gp::bench {

/// The name of the counter that holds the watched body's displacement over a run [m].
inline constexpr const char* kMovedCounter = "moved_m";
/// The name of the counter of body-steps per second of wall time.
inline constexpr const char* kBodyStepsCounter = "body_steps_per_s";
/// Counter of each run: the heap the engine held at its end [bytes] (TimedRun::heap_bytes).
inline constexpr const char* kHeapCounter = "heap_bytes";

/// Registers "<workload>/<engine>" for each workload and engine, the engines of a workload one
/// after another (ours, chipmunk, box2d), each as 1 iteration per repetition with the wall-clock
/// time of time_run as its manual time, in ms. `list` must outlive the run of the benchmarks.
void register_benchmarks(const std::vector<Workload>& list);

}  // namespace gp::bench
