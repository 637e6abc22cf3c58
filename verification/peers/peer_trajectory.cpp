#include "verification/peers/peer_trajectory.hpp"

#include "engine/output/trajectory.hpp"

namespace gp::peers {

PeerTrajectoryCsv::PeerTrajectoryCsv(std::ostream& out) : out_(out) {
  out_ << kTrajectoryHeader << '\n';
}

void PeerTrajectoryCsv::write(double t, const PeerWorld& world) {
  for (BodyId body = 0; body < world.body_count(); ++body) {
    write_row(out_, t, world.name(body), world.state(body));
  }
}

}  // namespace gp::peers
