#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:angAccel — angular acceleration α = dω/dt, integrated over a step of length h.
///   Δω = ∫ α dt = ᾱ h
/// @param mean_angular_acceleration  ᾱ, the mean angular acceleration over the step [rad/s²]
/// @param step                       h [s]
/// @return change of angular velocity Δω over the step [rad/s]
template <class AngularVelocity = double, class AngularAcceleration = double, class Time = double>
inline AngularVelocity angular_velocity_change_from_acceleration(
    models::In<AngularAcceleration> mean_angular_acceleration, models::In<Time> step) {
  return mean_angular_acceleration * step;
}

GP_REGISTER_MODEL("DD:angAccel", dd, angular_velocity_change_from_acceleration);

}  // namespace gp::dd
