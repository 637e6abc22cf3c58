#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:torque — torque of a force about a point, τ = r × F (its z-component, in 2D).
///   τ = r_x F_y − r_y F_x
/// Applied to an impulse J instead of a force it gives the angular impulse r × J [N·m·s].
/// @param arm    r, from the point (the centre of mass) to where the force acts [m]
/// @param force  F [N]
/// @return τ [N·m], positive counter-clockwise (A:axesDefined)
inline double torque(const Vec2& arm, const Vec2& force) {
  return cross(arm, force);
}

GP_REGISTER_MODEL("DD:torque", dd, torque);

}  // namespace gp::dd
