#include "engine/scene/run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "engine/output/output_times.hpp"

namespace gp {

namespace {
// An interval within this fraction of dt of a whole number of steps takes that number, each
// exactly dt, rather than one more sliver of a step. It is far above the rounding of
// interval / dt for the n ≤ 1e9 steps load_scene allows, so a shortened step is never ≤ 0.
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
    const double in_steps = interval / scene.dt;
    const auto steps =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(in_steps - kStepTolerance)));
    // A whole number of steps ends with one of dt too, not with one made to land on the instant
    // to the last bit: how often a run reports must not change its steps, and a pile, whose
    // motion grows every difference, would end elsewhere.
    const bool whole = in_steps >= static_cast<double>(steps) - kStepTolerance;
    for (std::int64_t i = 1; i < steps; ++i) step(scene.dt);
    step(whole ? scene.dt : interval - static_cast<double>(steps - 1) * scene.dt);
    at_output(times[k]);
  }
}

}  // namespace gp
