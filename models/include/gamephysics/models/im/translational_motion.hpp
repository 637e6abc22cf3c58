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
inline Vec2 translational_acceleration(const Vec2& gravity, const Vec2& force, double mass) {
  return gravity + tm::acceleration_from_force(force, mass);
}

GP_REGISTER_MODEL("IM:transMot", im, translational_acceleration, "TM:NewtonSecLawMot");

}  // namespace gp::im
