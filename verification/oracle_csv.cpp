#include "verification/oracle_csv.hpp"

#include <array>
#include <cstdio>

#include "engine/output/trajectory.hpp"

namespace gp::verification {

void write_trajectory(std::ostream& out, const Scene& scene, const OracleResult& result) {
  out << kTrajectoryHeader << '\n';
  for (std::size_t k = 0; k < result.times.size(); ++k) {
    for (std::size_t body = 0; body < scene.bodies.size(); ++body) {
      write_row(out, result.times[k], scene.bodies[body].name, result.states[k][body]);
    }
  }
}

void write_impacts(std::ostream& out, const Scene& scene, const OracleResult& result) {
  out << kImpactHeader << '\n';
  for (const OracleEvent& e : result.events) {
    write_number(out, e.time);
    out << ',' << scene.bodies[e.body_a].name << ',' << scene.bodies[e.body_b].name;
    for (double value : {e.normal.x(), e.normal.y(), e.impulse}) {
      out << ',';
      write_number(out, value);
    }
    out << '\n';
  }
}

}  // namespace gp::verification
