#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:coeffRestitution — coefficient of restitution measured from a collision.
///   C_R = −(v_f^AB · n) / (v_i^AB · n)
/// @param final_relative_velocity    v_f^AB after the collision [m/s]
/// @param initial_relative_velocity  v_i^AB before the collision [m/s], v_i^AB · n ≠ 0
/// @param normal                     collision normal n [1]
/// @return C_R [1]
template <class Restitution = double, class Velocity = Vec2, class Normal = Vec2>
inline Restitution coefficient_of_restitution(models::In<Velocity> final_relative_velocity,
                                              models::In<Velocity> initial_relative_velocity,
                                              models::In<Normal> normal) {
  return -dot(final_relative_velocity, normal) / dot(initial_relative_velocity, normal);
}

GP_REGISTER_MODEL("DD:coeffRestitution", dd, coefficient_of_restitution);

}  // namespace gp::dd
