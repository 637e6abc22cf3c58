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
inline double coefficient_of_restitution(const Vec2& final_relative_velocity,
                                         const Vec2& initial_relative_velocity,
                                         const Vec2& normal) {
  return -final_relative_velocity.dot(normal) / initial_relative_velocity.dot(normal);
}

GP_REGISTER_MODEL("DD:coeffRestitution", dd, coefficient_of_restitution);

}  // namespace gp::dd
