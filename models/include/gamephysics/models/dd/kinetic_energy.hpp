#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:kEnergy — kinetic energy of a rigid body, translational plus rotational.
///   KE = m ‖v‖² / 2 + I ω² / 2
/// The SRS gives only the first term (srs/errata.md E-DD-KENERGY).
/// @param mass              m [kg]
/// @param velocity          v of the centre of mass [m/s]
/// @param moment            I about the centre of mass [kg·m²]
/// @param angular_velocity  ω [rad/s]
/// @return KE [J]
template <class Energy = double, class Mass = double, class Velocity = Vec2, class Moment = double,
          class AngularVelocity = double>
inline Energy kinetic_energy(models::In<Mass> mass, models::In<Velocity> velocity,
                             models::In<Moment> moment,
                             models::In<AngularVelocity> angular_velocity) {
  return 0.5 * mass * squared_norm(velocity) + 0.5 * moment * angular_velocity * angular_velocity;
}

GP_REGISTER_MODEL("DD:kEnergy", dd, kinetic_energy);

}  // namespace gp::dd
