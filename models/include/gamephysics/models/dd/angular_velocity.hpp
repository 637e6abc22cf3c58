#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:angVel — angular velocity ω = dθ/dt, integrated over a step of length h.
///   θ = ∫ ω dt = ω̄ h
/// @param mean_angular_velocity  ω̄, the mean angular velocity over the step [rad/s]
/// @param step                   h [s]
/// @return angular displacement θ over the step [rad]
template <class Angle = double, class AngularVelocity = double, class Time = double>
inline Angle angular_displacement_from_velocity(models::In<AngularVelocity> mean_angular_velocity,
                                                models::In<Time> step) {
  return mean_angular_velocity * step;
}

GP_REGISTER_MODEL("DD:angVel", dd, angular_displacement_from_velocity);

}  // namespace gp::dd
