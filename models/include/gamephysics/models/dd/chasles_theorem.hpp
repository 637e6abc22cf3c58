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
template <class Velocity = Vec2, class AngularVelocity = double, class Offset = Vec2>
inline Velocity point_velocity(models::In<Velocity> velocity_origin,
                               models::In<AngularVelocity> angular_velocity,
                               models::In<Offset> offset) {
  return velocity_origin + cross(angular_velocity, offset);
}

GP_REGISTER_MODEL("DD:chaslesThm", dd, point_velocity);

}  // namespace gp::dd
