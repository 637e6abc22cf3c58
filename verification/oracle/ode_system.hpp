#pragma once
// The equations of motion of a Space as one first-order ODE system y' = f(t, y) for a solver:
// y holds x, y, ϕ, vx, vy, ω of every dynamic body (in ForceModel::bodies() order), and f is
// dp/dt = v, dϕ/dt = ω, dv/dt and dω/dt from the space's own ForceModel (IM:transMot,
// IM:rotMot). Kinematic bodies are not in y: their motion at constant velocity is known in
// closed form. Static bodies never move.

#include <cstddef>
#include <vector>

#include "engine/space.hpp"

namespace gp::verification {

class OdeSystem {
 public:
  /// Components of y per dynamic body: x, y [m], ϕ [rad], vx, vy [m/s], ω [rad/s].
  static constexpr std::size_t kPerBody = 6;

  /// Reads the bodies and their state at t₀ = space.time(); keeps a reference to the space's
  /// force model, so `space` must outlive this system.
  explicit OdeSystem(const Space& space);

  std::size_t size() const { return kPerBody * dynamic_.size(); }
  double initial_time() const { return t0_; }

  /// y at t₀.
  void initial_values(double* y) const;
  /// The state of every body at time t [s]: dynamic bodies from y, kinematic ones from their
  /// constant velocities, static ones where they are. Orientations are not reduced to [0, 2π):
  /// y carries ϕ continuously, so that the solver sees no jump.
  void state_at(double t, const double* y, MotionState& s) const;
  /// y from the dynamic bodies of `s` (after an impulse changed their velocities).
  void values_of(const MotionState& s, double* y) const;
  /// The accelerations [m/s², rad/s²] of the dynamic bodies in state `s` at time t [s].
  void accelerations(double t, const MotionState& s, Accelerations& a) const;
  /// f(t, y) into `dydt`. Not reentrant: uses scratch storage.
  void derivative(double t, const double* y, double* dydt);

 private:
  const ForceModel& forces_;
  std::vector<BodyId> dynamic_;
  std::vector<BodyId> kinematic_;
  double t0_;
  MotionState initial_;
  // Scratch for derivative(), kept so that a right-hand side does not allocate.
  MotionState scratch_;
  Accelerations acceleration_;
};

}  // namespace gp::verification
