#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:reVeInColl — initial relative velocity of rigid bodies A and B at the contact point P.
///   v_i^AB = v^AP − v^BP
/// @param velocity_a_at_contact  v^AP, velocity of the point P of body A (DD:chaslesThm) [m/s]
/// @param velocity_b_at_contact  v^BP, velocity of the point P of body B [m/s]
/// @return v_i^AB [m/s]
template <class Velocity = Vec2>
inline Velocity relative_velocity(models::In<Velocity> velocity_a_at_contact,
                                  models::In<Velocity> velocity_b_at_contact) {
  return velocity_a_at_contact - velocity_b_at_contact;
}

GP_REGISTER_MODEL("DD:reVeInColl", dd, relative_velocity);

}  // namespace gp::dd
