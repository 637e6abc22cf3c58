#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/tm/newton_second_law.hpp"
#include "gamephysics/models/tm/universal_gravitation.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::gd {

/// GD:accelGravity — acceleration due to gravity of a large mass M.
///   g = −G M / ‖d‖² · d̂
/// Derived as in the SRS: the force of TM:UniversalGravLaw on a test mass, divided by that mass
/// with TM:NewtonSecLawMot (an edge the SRS's matrix leaves out: srs/errata.md
/// E-TRACE-DERIVATION-EDGES).
/// @param G         gravitational constant [m³/(kg·s²)]
/// @param mass      mass M of the attracting body [kg]
/// @param distance  d, from the attracting body's centre of mass to the attracted point [m], d ≠ 0
/// @return gravitational acceleration g at the attracted point [m/s²], directed towards M
template <class Acceleration = Vec2, class GravitationalConstant = double, class Mass = double,
          class Displacement = Vec2>
inline Acceleration gravitational_acceleration(models::In<GravitationalConstant> G,
                                               models::In<Mass> mass,
                                               models::In<Displacement> distance) {
  using Force = models::Product<Acceleration, Mass>;
  // A unit test mass makes force and acceleration numerically equal (F = m g with m = 1 kg).
  const Mass test_mass = models::one<Mass>();
  return tm::acceleration_from_force<Acceleration, Force, Mass>(
      tm::gravitational_force<Force, GravitationalConstant, Mass, Displacement>(G, test_mass, mass,
                                                                                -distance),
      test_mass);
}

GP_REGISTER_MODEL("GD:accelGravity", gd, gravitational_acceleration, "TM:UniversalGravLaw",
                  "TM:NewtonSecLawMot");

}  // namespace gp::gd
