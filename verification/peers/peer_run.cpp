#include "verification/peers/peer_run.hpp"

#include "engine/scene/run.hpp"

namespace gp::peers {

void run_peer(PeerWorld& world, const Scene& scene,
              const std::function<void(double t)>& at_output) {
  run_steps(
      scene, [&world](double dt) { world.step(dt); }, at_output);
}

}  // namespace gp::peers
