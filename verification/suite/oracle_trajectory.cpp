#include "verification/suite/oracle_trajectory.hpp"

#include <ctime>

#include "engine/scene/scene_space.hpp"

namespace gp::verification {

Trajectory run_oracle_trajectory(const Scene& scene, std::span<const double> times,
                                 const OracleOptions& options) {
  const std::clock_t start = std::clock();
  OracleResult result = run_oracle(scene, times, options);
  Trajectory t;
  t.cpu_seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  t.times = std::move(result.times);
  t.states = std::move(result.states);
  for (const OracleEvent& e : result.events) {
    t.impacts.push_back({e.time, static_cast<BodyId>(e.body_a), static_cast<BodyId>(e.body_b),
                         e.normal, e.point, e.impulse});
  }
  return t;
}

}  // namespace gp::verification
