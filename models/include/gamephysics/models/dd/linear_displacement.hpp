#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:linDisp — linear displacement u = p(t) − p(t₀), solved for the new position.
/// (The SRS writes u = dp/dt, which is a velocity: srs/errata.md E-DD-LINDISP.)
///   p(t) = p(t₀) + u
/// @param position      p(t₀) [m]
/// @param displacement  u over [t₀, t] [m]
/// @return p(t) [m]
template <class Position = Vec2>
inline Position displaced_position(models::In<Position> position,
                                   models::In<Position> displacement) {
  return position + displacement;
}

GP_REGISTER_MODEL("DD:linDisp", dd, displaced_position);

}  // namespace gp::dd
