#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::tm {

/// TM:NewtonSecLawMot — Newton's second law of motion, F = m a, solved for the acceleration.
///   a = F / m
/// @param force  net force F on the body [N]
/// @param mass   mass m of the body [kg], m > 0
/// @return acceleration a of the body [m/s²]
template <class Acceleration = Vec2, class Force = Vec2, class Mass = double>
inline Acceleration acceleration_from_force(models::In<Force> force, models::In<Mass> mass) {
  return force / mass;
}

GP_REGISTER_MODEL("TM:NewtonSecLawMot", tm, acceleration_from_force);

}  // namespace gp::tm
