#include "verification/peers/peer_trajectory.hpp"

#include <array>
#include <cstdio>

#include "engine/output/trajectory.hpp"

namespace gp::peers {

namespace {

// TrajectoryCsv (src/engine/output/trajectory.cpp) reads its rows from a Space only; the format
// of a number is repeated here: 17 significant digits identify every double.
void put(std::ostream& out, double value) {
  std::array<char, 32> text{};
  const int length = std::snprintf(text.data(), text.size(), "%.17g", value);
  out.write(text.data(), length);
}

}  // namespace

PeerTrajectoryCsv::PeerTrajectoryCsv(std::ostream& out) : out_(out) {
  out_ << kTrajectoryHeader << '\n';
}

void PeerTrajectoryCsv::write(double t, const PeerWorld& world) {
  for (BodyId body = 0; body < world.body_count(); ++body) {
    const BodyState s = world.state(body);
    put(out_, t);
    out_ << ',' << world.name(body);
    for (double value : {s.position.x(), s.position.y(), s.angle, s.velocity.x(), s.velocity.y(),
                         s.angular_velocity}) {
      out_ << ',';
      put(out_, value);
    }
    out_ << '\n';
  }
}

}  // namespace gp::peers
