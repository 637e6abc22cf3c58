#pragma once
// A scene run by a peer engine (Chipmunk2D, Box2D) as the verification suite compares it.

#include "verification/peers/peer_world.hpp"
#include "verification/suite/trajectory.hpp"

namespace gp::verification {

/// The scene run by `engine` at the scene's dt, its state recorded after every step.
Trajectory run_peer_trajectory(peers::PeerEngine engine, const Scene& scene);

/// CPU seconds `engine` takes to run the scene at its dt without recording anything, as
/// time_engine() measures ours (building the world left out).
double time_peer(peers::PeerEngine engine, const Scene& scene);

}  // namespace gp::verification
