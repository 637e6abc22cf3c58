#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::tm {

/// TM:NewtonSecLawRotMot — Newton's second law for rotational motion, τ = I α, solved for α.
/// In 2D (A:objectDimension) τ and α are the z-components of the SRS's vectors, and I is the
/// scalar moment about the z-axis through the centre of mass.
///   α = τ / I
/// @param torque  net torque τ about the centre of mass [N·m]
/// @param moment  moment of inertia I [kg·m²], I > 0
/// @return angular acceleration α [rad/s²]
template <class AngularAcceleration = double, class Torque = double, class Moment = double>
inline AngularAcceleration angular_acceleration_from_torque(models::In<Torque> torque,
                                                            models::In<Moment> moment) {
  return torque / moment;
}

GP_REGISTER_MODEL("TM:NewtonSecLawRotMot", tm, angular_acceleration_from_torque);

}  // namespace gp::tm
