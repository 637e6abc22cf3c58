#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/tm/newton_second_law.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::im {

/// IM:transMot — acceleration of the j-th body: the right-hand side of the translational ODE
/// shared by the game integrators and the oracle.
///   a_j(t) = g + F_j(t) / m_j
/// Positions and velocities follow from DD:linDisp, DD:linVel and DD:linAcc.
/// @param gravity  g, gravitational acceleration at the body (uniform, or from GD:accelGravity)
///                 [m/s²]
/// @param force    F_j(t), sum of the other forces applied to the body [N]
/// @param mass     m_j [kg], m_j > 0
/// @return a_j [m/s²]
template <class Acceleration = Vec2, class Force = Vec2, class Mass = double>
inline Acceleration translational_acceleration(models::In<Acceleration> gravity,
                                               models::In<Force> force, models::In<Mass> mass) {
  return gravity + tm::acceleration_from_force<Acceleration, Force, Mass>(force, mass);
}

GP_REGISTER_MODEL("IM:transMot", im, translational_acceleration, "TM:NewtonSecLawMot");

}  // namespace gp::im
