#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:linAcc — linear acceleration a = dv/dt, integrated over a step of length h.
///   Δv = ∫ a dt = ā h
/// @param mean_acceleration  ā, the mean acceleration over the step [m/s²]
/// @param step               h [s]
/// @return change of velocity Δv over the step [m/s]
template <class Velocity = Vec2, class Acceleration = Vec2, class Time = double>
inline Velocity velocity_change_from_acceleration(models::In<Acceleration> mean_acceleration,
                                                  models::In<Time> step) {
  return mean_acceleration * step;
}

GP_REGISTER_MODEL("DD:linAcc", dd, velocity_change_from_acceleration);

}  // namespace gp::dd
