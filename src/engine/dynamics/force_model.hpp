#pragma once
// The force stage: the accelerations of the dynamic bodies from uniform gravity, pairwise
// gravitation (TM:UniversalGravLaw, GD:accelGravity), applied forces and torques, forces applied
// at a point (DD:torque) and time-dependent forces, through IM:transMot and IM:rotMot.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "engine/core.hpp"
#include "engine/force_callback.hpp"
#include "scene/settings.hpp"

namespace gp {

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
  explicit ForceModel(const Settings& settings);

  /// Registers a dynamic body (ids must be added in increasing order).
  void add(BodyId id, BodyForces forces);
  /// Adds a time-dependent force to dynamic body `id`, whose inverse moment of inertia is
  /// `inverse_moment` (1/(kg·m²), 0 if it does not rotate).
  void set_callback(BodyId id, double inverse_moment, ForceCallback callback);

  /// Adds a force [N] at the centre of mass and a torque [N·m] to dynamic body `id` (inverse
  /// moment as for set_callback) for the next step only, as a constant force does; end_step()
  /// takes them away again.
  void add_for_next_step(BodyId id, double inverse_moment, const Wrench& wrench);
  /// Ends a step: the forces of add_for_next_step are gone, and the model is again exactly as it
  /// was before them.
  void end_step();
  /// Removes dynamic body `id`, which no longer pushes or is pushed.
  void remove(BodyId id);

  /// Accelerations of the dynamic bodies at time `t` in state `s` (other entries untouched).
  void evaluate(double t, const MotionState& s, Accelerations& out) const;

  /// True when the accelerations depend on neither time nor state, so one evaluation serves a
  /// whole step.
  bool constant() const;
  bool pairwise_gravitation() const { return G_.has_value(); }
  bool any_applied() const;
  /// Under constant forces (constant()), the accelerations of dynamic body `body`, the same for
  /// every body of gravity only: none needs one stored.
  Vec2 constant_linear_acceleration(BodyId body) const {
    const Pushed* p = pushed(body);
    return p ? p->linear : falling_;
  }
  double constant_angular_acceleration(BodyId body) const {
    const Pushed* p = pushed(body);
    return p ? p->angular : 0.0;
  }
  /// Under constant forces, calls visit(k, j, a, α) for each dynamic body, entry k of bodies()
  /// and id j, with its linear and angular accelerations, in order: one pass over the bodies
  /// without a look-up for each.
  template <typename Visit>
  void for_each_constant_acceleration(Visit visit) const {
    auto pushed = pushed_.begin();
    for (std::size_t k = 0; k < ids_.size(); ++k) {
      const BodyId j = ids_[k];
      if (pushed != pushed_.end() && pushed->body == j) {
        visit(k, j, pushed->linear, pushed->angular);
        ++pushed;
      } else {
        visit(k, j, falling_, 0.0);
      }
    }
  }
  /// Whether the body at entry `entry` of bodies() feels gravity alone: no applied force or
  /// torque, constant, at a point, for the next step or given by a callback.
  bool gravity_only(std::size_t entry) const {
    if (applied_.empty()) return true;  // the common case
    return !std::binary_search(
        applied_.begin(), applied_.end(), entry,
        [](const auto& x, const auto& y) { return entry_of(x) < entry_of(y); });
  }
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
    Wrench next_step{};  ///< for the next step only (add_for_next_step)
  };
  /// The accelerations of a body pushed beyond gravity by constant forces.
  struct Pushed {
    BodyId body;
    Vec2 linear;     ///< m/s²
    double angular;  ///< rad/s²
  };
  static std::size_t entry_of(const Applied& a) { return a.entry; }
  static std::size_t entry_of(std::size_t entry) { return entry; }
  /// Whether `forces` push the body beyond gravity, so that it needs an Applied.
  static bool beyond_gravity(const BodyForces& forces);
  /// The constant accelerations of `body` under `applied`, with its forces for the next step.
  Pushed pushed_by(BodyId body, const Applied& applied, bool with_next_step) const;
  /// The Applied of entry `entry` of bodies() in `applied`, made for a body of gravity only so
  /// far, whose inverse moment is `inverse_moment`.
  std::vector<Applied>::iterator applied_at(std::vector<Applied>& applied, std::uint32_t entry,
                                            double inverse_moment) const;
  /// Calls change(applied, pushed) on applied_ and pushed_, and on the ones end_step() will
  /// restore, so that a change made between add_for_next_step and the step outlasts the step.
  template <typename Change>
  void in_each(Change change);
  /// The Pushed of `body`, null for a body of gravity only.
  const Pushed* pushed(BodyId body) const {
    if (pushed_.empty()) return nullptr;  // the common case: gravity alone
    const auto it = std::lower_bound(pushed_.begin(), pushed_.end(), body,
                                     [](const Pushed& p, BodyId b) { return p.body < b; });
    return it != pushed_.end() && it->body == body ? &*it : nullptr;
  }

  Vec2 gravity_;
  Vec2 falling_;  // m/s²: the acceleration of a body of gravity only
  std::optional<double> G_;
  std::vector<BodyId> ids_;
  std::vector<double> masses_;  // per entry of bodies()
  std::vector<char> rotates_;
  // Most bodies of a game feel gravity only: only the others keep their forces, by entry.
  std::vector<Applied> applied_;
  // Their accelerations under constant forces, by body id; meaningless, and unread, for forces
  // applied at a point or given by a callback, which are not constant.
  std::vector<Pushed> pushed_;
  // applied_ and pushed_ as they were before add_for_next_step, restored by end_step().
  struct Saved {
    std::vector<Applied> applied;
    std::vector<Pushed> pushed;
  };
  std::optional<Saved> before_next_step_;
};

/// The accelerations of the bodies at the start of a step, which the ballistic paths follow: under
/// constant forces the ForceModel's, so that nothing is stored per body, else evaluated per body.
/// Bodies that are not dynamic have none.
class StepAccelerations {
 public:
  /// Under constant forces, for the bodies flagged in `dynamic`, indexed by body id.
  StepAccelerations(const ForceModel& forces, const std::vector<char>& dynamic)
      : forces_(&forces), dynamic_(&dynamic) {}
  /// Evaluated per body.
  explicit StepAccelerations(const Accelerations& evaluated) : evaluated_(&evaluated) {}

  Vec2 linear(BodyId body) const {
    if (evaluated_) return evaluated_->linear[body];
    return (*dynamic_)[body] ? forces_->constant_linear_acceleration(body) : Vec2::Zero();
  }
  double angular(BodyId body) const {
    if (evaluated_) return evaluated_->angular[body];
    return (*dynamic_)[body] ? forces_->constant_angular_acceleration(body) : 0.0;
  }

 private:
  const ForceModel* forces_ = nullptr;
  const std::vector<char>* dynamic_ = nullptr;
  const Accelerations* evaluated_ = nullptr;
};

}  // namespace gp
