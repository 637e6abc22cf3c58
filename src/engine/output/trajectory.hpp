#pragma once
// The trajectory of a run as CSV: the SRS outputs p(t), ϕ(t), v(t), ω(t) of every body at each
// output instant.

#include <ostream>
#include <string_view>

#include "engine/space.hpp"

namespace gp {

/// The header: time [s], the body's name, centre of mass x, y [m], orientation ϕ [rad] in
/// [0, 2π), velocity of the centre of mass vx, vy [m/s], angular velocity ω [rad/s].
inline constexpr std::string_view kTrajectoryHeader = "t,body,x,y,angle,vx,vy,omega";

/// A number as the trajectory CSV writes it: as printf's "%.17g", so that reading it back gives
/// the same double.
void write_number(std::ostream& out, double value);

/// One row: time t [s], the body's name, its state.
void write_row(std::ostream& out, double t, std::string_view name, const BodyState& state);

/// Writes CSV rows with every number as %.17g, so that reading one back gives the same double.
class TrajectoryCsv {
 public:
  /// Writes the header line to `out`, which must outlive this writer.
  explicit TrajectoryCsv(std::ostream& out);

  /// One row per body of `space`, in BodyId order, labelled with time t [s]: the exact output
  /// instant, of which space.time(), a sum of steps, is only an approximation.
  void write(double t, const Space& space);

 private:
  std::ostream& out_;
};

}  // namespace gp
