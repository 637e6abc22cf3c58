#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::tm {

/// TM:NewtonSecLawMot — Newton's second law of motion, F = m a, solved for the acceleration.
///   a = F / m
/// @param force  net force F on the body [N]
/// @param mass   mass m of the body [kg], m > 0
/// @return acceleration a of the body [m/s²]
inline Vec2 acceleration_from_force(const Vec2& force, double mass) {
  return force / mass;
}

GP_REGISTER_MODEL("TM:NewtonSecLawMot", tm, acceleration_from_force);

}  // namespace gp::tm
