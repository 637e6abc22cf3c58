#include "verification/suite/peer_trajectory.hpp"

#include <algorithm>

#include "verification/peers/peer_run.hpp"
#include "verification/peers/peer_scene.hpp"

namespace gp::verification {

Trajectory run_peer_trajectory(peers::PeerEngine engine, const Scene& scene) {
  Scene stepped = scene;
  stepped.output_dt = scene.dt;
  const auto world = peers::make_peer(engine, peers::peer_scene(stepped));
  Trajectory run;
  peers::run_peer(*world, stepped, [&](double t) {
    run.times.push_back(t);
    std::vector<BodyState> states;
    for (BodyId id = 0; id < world->body_count(); ++id) states.push_back(world->state(id));
    run.states.push_back(std::move(states));
  });
  return run;
}

double time_peer(peers::PeerEngine engine, const Scene& scene) {
  Scene stepped = scene;
  stepped.output_dt = std::max(scene.duration, scene.dt);
  return median_cpu_seconds([&] {
    const auto world = peers::make_peer(engine, peers::peer_scene(stepped));
    const double start = cpu_now();
    peers::run_peer(*world, stepped, [](double) {});
    return cpu_now() - start;
  });
}

}  // namespace gp::verification
