#pragma once
// The oracle's results as CSV: its trajectory in the format of `gamephysics simulate`
// (src/engine/output/trajectory.hpp), so that the two files compare row by row, and its impacts.

#include <ostream>
#include <string_view>

#include "scene/scene.hpp"
#include "verification/oracle/oracle.hpp"

namespace gp::verification {

/// The header of the impact log: t_c [s], the names of bodies A and B, the unit normal from B
/// towards A, the impulse j [N·s] on A (−j n on B).
inline constexpr std::string_view kImpactHeader = "t,body_a,body_b,nx,ny,impulse";

/// kTrajectoryHeader, then one row per output instant and body of `scene` (named as in it),
/// every number as %.17g so that reading one back gives the same double.
void write_trajectory(std::ostream& out, const Scene& scene, const OracleResult& result);

/// kImpactHeader, then one row per impact of `result`, in time order.
void write_impacts(std::ostream& out, const Scene& scene, const OracleResult& result);

}  // namespace gp::verification
