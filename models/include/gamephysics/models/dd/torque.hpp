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
template <class Torque = double, class Arm = Vec2, class Force = Vec2>
inline Torque torque(models::In<Arm> arm, models::In<Force> force) {
  return cross(arm, force);
}

GP_REGISTER_MODEL("DD:torque", dd, torque);

}  // namespace gp::dd
