#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:impulseV — impulse (vector) J = m Δv, solved for the change of velocity it causes.
///   Δv = J / m
/// @param impulse       J [N·s]
/// @param inverse_mass  1/m [1/kg]; 0 for an immovable body, which no impulse moves
/// @return Δv [m/s]
template <class Velocity = Vec2, class Impulse = Vec2, class InverseMass = double>
inline Velocity velocity_change_from_impulse(models::In<Impulse> impulse,
                                             models::In<InverseMass> inverse_mass) {
  return impulse * inverse_mass;
}

GP_REGISTER_MODEL("DD:impulseV", dd, velocity_change_from_impulse);

}  // namespace gp::dd
