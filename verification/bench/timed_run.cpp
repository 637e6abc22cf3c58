#include "verification/bench/timed_run.hpp"

#include <chrono>

namespace gp::bench {

TimedRun time_run(const Workload& w, Engine engine) {
  EngineRun run(engine, w.scene);
  const Vec2 start = w.watched ? run.state(*w.watched).position : Vec2::Zero();
  // steady_clock: wall time that no clock adjustment during the run can shift.
  const auto begin = std::chrono::steady_clock::now();
  for (int i = 0; i < w.steps; ++i) run.step(w.scene.dt);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - begin;
  TimedRun timed{elapsed.count()};
  if (w.watched) timed.moved_m = (run.state(*w.watched).position - start).norm();
  return timed;
}

}  // namespace gp::bench
