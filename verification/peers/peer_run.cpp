#include "verification/peers/peer_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "engine/output/output_times.hpp"

namespace gp::peers {

namespace {
// run_scene's rule (src/engine/scene/run.cpp), which that function keeps private: an interval
// within this fraction of dt of a whole number of steps takes that number of steps.
constexpr double kStepTolerance = 1e-6;
}  // namespace

void run_peer(PeerWorld& world, const Scene& scene,
              const std::function<void(double t)>& at_output) {
  const OutputTimes times(scene.duration, scene.output_dt);
  at_output(times[0]);
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double interval = times[k] - times[k - 1];
    const auto steps = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::ceil(interval / scene.dt - kStepTolerance)));
    for (std::int64_t i = 1; i < steps; ++i) world.step(scene.dt);
    world.step(interval - static_cast<double>(steps - 1) * scene.dt);
    at_output(times[k]);
  }
}

}  // namespace gp::peers
