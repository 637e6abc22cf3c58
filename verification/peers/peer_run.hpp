#pragma once
// A run of a scene in a peer engine, with the same steps and output instants as run_scene gives
// our Space, so that the two trajectories are comparable row by row.

#include <functional>

#include "scene/scene.hpp"
#include "verification/peers/peer_world.hpp"

namespace gp::peers {

/// Steps `world`, made from `scene` and still at t = 0, to scene.duration with the steps
/// run_scene takes: steps of scene.dt, the step that would cross an output instant shortened to
/// end on it; calls at_output(t) at each instant (OutputTimes), t = 0 first.
void run_peer(PeerWorld& world, const Scene& scene, const std::function<void(double t)>& at_output);

}  // namespace gp::peers
