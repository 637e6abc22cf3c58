#include "engine/scene/run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "engine/output/output_times.hpp"

namespace gp {

namespace {
// An interval within this fraction of dt of a whole number of steps takes that number, the last
// one a hair longer than dt, rather than one more sliver of a step. It is far above the rounding
// of (n - 1)·dt for the n ≤ 1e9 steps load_scene allows, so the last step is never ≤ 0.
constexpr double kStepTolerance = 1e-6;
}  // namespace

void run_scene(Space& space, const Scene& scene, const std::function<void(double t)>& at_output) {
  run_steps(
      scene, [&space](double dt) { space.step(dt); }, at_output);
}

void run_steps(const Scene& scene, const std::function<void(double dt)>& step,
               const std::function<void(double t)>& at_output) {
  const OutputTimes times(scene.duration, scene.output_dt);
  at_output(times[0]);
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double interval = times[k] - times[k - 1];
    const auto steps = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::ceil(interval / scene.dt - kStepTolerance)));
    for (std::int64_t i = 1; i < steps; ++i) step(scene.dt);
    step(interval - static_cast<double>(steps - 1) * scene.dt);
    at_output(times[k]);
  }
}

}  // namespace gp
