#include "verification/oracle/oracle_csv.hpp"

#include <array>
#include <cstdio>

#include "engine/output/trajectory.hpp"

namespace gp::verification {

void write_trajectory(std::ostream& out, const Space& space, const OracleResult& result) {
  out << kTrajectoryHeader << '\n';
  for (std::size_t k = 0; k < result.times.size(); ++k) {
    for (BodyId body = 0; body < space.body_count(); ++body) {
      write_row(out, result.times[k], space.name(body), result.states[k][body]);
    }
  }
}

void write_impacts(std::ostream& out, const Space& space, const OracleResult& result) {
  out << kImpactHeader << '\n';
  for (const OracleEvent& e : result.events) {
    write_number(out, e.time);
    out << ',' << space.name(e.body_a) << ',' << space.name(e.body_b);
    for (double value : {e.normal.x(), e.normal.y(), e.impulse}) {
      out << ',';
      write_number(out, value);
    }
    out << '\n';
  }
}

}  // namespace gp::verification
