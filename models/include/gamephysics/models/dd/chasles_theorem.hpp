#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:chaslesThm — velocity of a point B of a rigid body (Chasles' theorem).
///   v_B = v_O + ω × u_OB
/// In 2D ω is the z-component of the angular velocity, and ω × u = ω (−u_y, u_x).
/// @param velocity_origin   v_O, velocity of the reference point O (the centre of mass) [m/s]
/// @param angular_velocity  ω [rad/s]
/// @param offset            u_OB, from O to B [m]
/// @return v_B [m/s]
inline Vec2 point_velocity(const Vec2& velocity_origin, double angular_velocity,
                           const Vec2& offset) {
  return velocity_origin + cross(angular_velocity, offset);
}

GP_REGISTER_MODEL("DD:chaslesThm", dd, point_velocity);

}  // namespace gp::dd
