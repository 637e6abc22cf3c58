#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:potEnergy — potential energy in a uniform gravitational field.
///   PE = m ‖g‖ h = −m g · p
/// with the height h measured against g from the origin (the SRS multiplies the vector g by the
/// scalar h, which is not a scalar energy: srs/errata.md E-DD-POTENERGY).
/// @param mass      m [kg]
/// @param gravity   g [m/s²]
/// @param position  p of the centre of mass [m]
/// @return PE [J], zero at the origin
template <class Energy = double, class Mass = double, class Acceleration = Vec2,
          class Position = Vec2>
inline Energy potential_energy(models::In<Mass> mass, models::In<Acceleration> gravity,
                               models::In<Position> position) {
  return -mass * dot(gravity, position);
}

GP_REGISTER_MODEL("DD:potEnergy", dd, potential_energy);

}  // namespace gp::dd
