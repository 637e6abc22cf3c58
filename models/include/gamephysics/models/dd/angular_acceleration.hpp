#pragma once
#include "gamephysics/models/registry.hpp"

namespace gp::dd {

/// DD:angAccel — angular acceleration α = dω/dt, integrated over a step of length h.
///   Δω = ∫ α dt = ᾱ h
/// @param mean_angular_acceleration  ᾱ, the mean angular acceleration over the step [rad/s²]
/// @param step                       h [s]
/// @return change of angular velocity Δω over the step [rad/s]
inline double angular_velocity_change_from_acceleration(double mean_angular_acceleration,
                                                        double step) {
  return mean_angular_acceleration * step;
}

GP_REGISTER_MODEL("DD:angAccel", dd, angular_velocity_change_from_acceleration);

}  // namespace gp::dd
