#pragma once
// The trajectory of a peer run as the CSV that `gamephysics simulate` writes (kTrajectoryHeader,
// every number as %.17g), so that the same tools read ours and the peers'.

#include <ostream>

#include "verification/peers/peer_world.hpp"

namespace gp::peers {

class PeerTrajectoryCsv {
 public:
  /// Writes the header line to `out`, which must outlive this writer.
  explicit PeerTrajectoryCsv(std::ostream& out);

  /// One row per body of `world`, in BodyId order, labelled with the output instant t [s].
  void write(double t, const PeerWorld& world);

 private:
  std::ostream& out_;
};

}  // namespace gp::peers
