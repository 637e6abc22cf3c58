#include "verification/oracle/oracle_csv.hpp"

#include <array>
#include <cstdio>

#include "engine/output/trajectory.hpp"

namespace gp::verification {

namespace {

// "%.17g" identifies every double and needs at most 24 characters.
void put(std::ostream& out, double value) {
  std::array<char, 32> text{};
  const int length = std::snprintf(text.data(), text.size(), "%.17g", value);
  out.write(text.data(), length);
}

}  // namespace

void write_trajectory(std::ostream& out, const Space& space, const OracleResult& result) {
  out << kTrajectoryHeader << '\n';
  for (std::size_t k = 0; k < result.times.size(); ++k) {
    for (BodyId body = 0; body < space.body_count(); ++body) {
      const BodyState& s = result.states[k][body];
      put(out, result.times[k]);
      out << ',' << space.name(body);
      for (double value : {s.position.x(), s.position.y(), s.angle, s.velocity.x(), s.velocity.y(),
                           s.angular_velocity}) {
        out << ',';
        put(out, value);
      }
      out << '\n';
    }
  }
}

void write_impacts(std::ostream& out, const Space& space, const OracleResult& result) {
  out << kImpactHeader << '\n';
  for (const OracleEvent& e : result.events) {
    put(out, e.time);
    out << ',' << space.name(e.body_a) << ',' << space.name(e.body_b);
    for (double value : {e.normal.x(), e.normal.y(), e.impulse}) {
      out << ',';
      put(out, value);
    }
    out << '\n';
  }
}

}  // namespace gp::verification
