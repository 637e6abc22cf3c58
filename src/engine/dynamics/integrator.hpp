#pragma once
// The game integrators behind one interface (LC:Variable-ODE-Solver). Each advances the dynamic
// bodies over a step without contacts, from the right-hand sides of IM:transMot and IM:rotMot
// (through the ForceModel), turning accelerations into velocities and positions with DD:linAcc,
// DD:linVel, DD:linDisp and DD:angAccel, DD:angVel, DD:angDisp.

#include <memory>

#include "engine/dynamics/force_model.hpp"
#include "scene/settings.hpp"

namespace gp {

/// The path a body follows over a step of h under a constant acceleration a, as an integrator
/// takes it.
enum class PathShape {
  /// x₀ + v₀τ + ½aτ²: the exact motion (velocity Verlet, RK4).
  kParabola,
  /// x₀ + (v₀ + ah)τ: the straight line at the step's end velocity (symplectic Euler).
  kEndVelocity,
};

class Integrator {
 public:
  virtual ~Integrator() = default;

  /// Advances the bodies of `forces` in `s` from time t by h [s].
  virtual void advance(const ForceModel& forces, double t, double h, MotionState& s) = 0;

  /// How much of a velocity change Δv made by contact impulses during a step moves the body in
  /// that step, as a fraction of Δv·h: 1 when the position update uses the end velocity
  /// (symplectic Euler), ½ when it uses the mean of the start and end velocities (trapezoidal:
  /// velocity Verlet, RK4). With this share a body resting on the ground stays exactly still.
  virtual double impulse_position_share() const = 0;

  /// The path a step under constant accelerations lands on exactly, so that a step may start
  /// from any point of it (local impacts).
  virtual PathShape path_under_constant_acceleration() const = 0;
};

std::unique_ptr<Integrator> make_integrator(IntegratorKind kind);

}  // namespace gp
