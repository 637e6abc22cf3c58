#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/tm/newton_second_law_rotation.hpp"

namespace gp::im {

/// IM:rotMot — angular acceleration of the j-th body: the right-hand side of the rotational ODE
/// shared by the game integrators and the oracle.
///   α_j(t) = τ_j(t) / I
/// Orientation and angular velocity follow from DD:angDisp, DD:angVel and DD:angAccel.
/// @param torque  τ_j(t), net torque about the centre of mass [N·m]
/// @param moment  I about the centre of mass [kg·m²], I > 0
/// @return α_j [rad/s²] (of either sign: srs/errata.md E-IM-ROTMOT-SIGN)
template <class AngularAcceleration = double, class Torque = double, class Moment = double>
inline AngularAcceleration angular_acceleration(models::In<Torque> torque,
                                                models::In<Moment> moment) {
  return tm::angular_acceleration_from_torque<AngularAcceleration, Torque, Moment>(torque, moment);
}

GP_REGISTER_MODEL("IM:rotMot", im, angular_acceleration, "TM:NewtonSecLawRotMot");

}  // namespace gp::im
