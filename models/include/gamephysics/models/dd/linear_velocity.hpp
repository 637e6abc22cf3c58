#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:linVel — linear velocity v = du/dt, integrated over a step of length h.
///   u = ∫ v dt = v̄ h
/// where v̄ is the mean velocity over the step. Integrators choose v̄: v(t₀ + h) for symplectic
/// Euler, v(t₀) + ½ a h for velocity Verlet (exact under constant acceleration).
/// @param mean_velocity  v̄ [m/s]
/// @param step           h [s]
/// @return displacement u over the step [m]
inline Vec2 displacement_from_velocity(const Vec2& mean_velocity, double step) {
  return mean_velocity * step;
}

GP_REGISTER_MODEL("DD:linVel", dd, displacement_from_velocity);

}  // namespace gp::dd
