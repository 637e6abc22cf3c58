#pragma once
// The force stage: the accelerations of the dynamic bodies from uniform gravity, pairwise
// gravitation (TM:UniversalGravLaw, GD:accelGravity), applied forces and torques, forces applied
// at a point (DD:torque) and time-dependent forces, through IM:transMot and IM:rotMot.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "engine/body.hpp"
#include "engine/dynamics/motion_state.hpp"
#include "engine/settings.hpp"

namespace gp {

using BodyId = std::uint32_t;

/// F_j(t), τ_j(t) of one body, given the time [s] and the body's state at that time.
using ForceCallback = std::function<Wrench(double t, BodyId body, const BodyState& state)>;

/// What a dynamic body is pushed by; fixed when the body is added, except callbacks.
struct BodyForces {
  double mass;            ///< kg
  double inverse_moment;  ///< 1/(kg·m²); 0 if the body does not rotate
  Vec2 force;             ///< N, constant
  double torque;          ///< N·m, constant
  bool force_at_point;    ///< `force` acts at `arm` (body frame) rather than at the CoM
  Vec2 arm;               ///< m, body frame, from the CoM to where `force` acts
  ForceCallback callback;
};

class ForceModel {
 public:
  explicit ForceModel(const Settings& settings) : gravity_(settings.gravity), G_(settings.G) {}

  /// Registers a dynamic body (ids must be added in increasing order).
  void add(BodyId id, BodyForces forces);
  /// Adds a time-dependent force to dynamic body `id`, whose inverse moment of inertia is
  /// `inverse_moment` (1/(kg·m²), 0 if it does not rotate).
  void set_callback(BodyId id, double inverse_moment, ForceCallback callback);

  /// Accelerations of the dynamic bodies at time `t` in state `s` (other entries untouched).
  void evaluate(double t, const MotionState& s, Accelerations& out) const;

  /// True when the accelerations depend on neither time nor state, so one evaluation serves a
  /// whole step.
  bool constant() const;
  bool pairwise_gravitation() const { return G_.has_value(); }
  bool any_applied() const;
  /// The dynamic bodies, in increasing id order.
  const std::vector<BodyId>& bodies() const { return ids_; }
  /// Per entry of bodies(): whether the body can rotate (it has a moment of inertia). The
  /// integrators skip rotation for the others, whose ω stays 0.
  const std::vector<char>& rotates() const { return rotates_; }

 private:
  /// The forces of the body at entry `entry` of bodies(), when it has more than gravity.
  struct Applied {
    std::uint32_t entry;
    BodyForces forces;
  };
  /// Whether `forces` push the body beyond gravity, so that it needs an Applied.
  static bool beyond_gravity(const BodyForces& forces);

  Vec2 gravity_;
  std::optional<double> G_;
  std::vector<BodyId> ids_;
  std::vector<double> masses_;  // per entry of bodies()
  std::vector<char> rotates_;
  // Most bodies of a game feel gravity only: only the others keep their forces, by entry.
  std::vector<Applied> applied_;
};

}  // namespace gp
