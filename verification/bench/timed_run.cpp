#include "verification/bench/timed_run.hpp"

#include <malloc.h>

#include <chrono>

#include <tbb/task_arena.h>

namespace gp::bench {

namespace {

// Bytes handed out by malloc and not yet freed, the large blocks it maps apart included. Every
// engine allocates through malloc (Box2D's block allocator takes its chunks from it), so this
// measures all three alike.
double heap_in_use() {
  const struct mallinfo2 heap = mallinfo2();
  return static_cast<double>(heap.uordblks + heap.hblkhd);
}

// time_run on the threads of the current task arena.
TimedRun time_run_here(const Workload& w, Engine engine, const AroundSteps& around) {
  const double heap_before = heap_in_use();
  EngineRun run(engine, w.scene);
  const Vec2 start = w.watched ? run.state(*w.watched).position : Vec2::Zero();
  if (around.before) around.before();
  // steady_clock: wall time that no clock adjustment during the run can shift.
  const auto begin = std::chrono::steady_clock::now();
  for (int i = 0; i < w.steps; ++i) run.step(w.scene.dt);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - begin;
  if (around.after) around.after();
  TimedRun timed{elapsed.count()};
  if (w.watched) timed.moved_m = (run.state(*w.watched).position - start).norm();
  timed.heap_bytes = heap_in_use() - heap_before;
  return timed;
}

}  // namespace

TimedRun time_run(const Workload& w, Engine engine, const AroundSteps& around, int threads) {
  tbb::task_arena arena(threads);
  return arena.execute([&] { return time_run_here(w, engine, around); });
}

}  // namespace gp::bench
