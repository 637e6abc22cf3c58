#pragma once
// The collisions of the oracle as events of the ODE (FR:Determine-Collisions): one root function
// per pair of shapes that can collide — their signed distance — and, at a root, the impact
// resolved by IM:col2D (FR:Determine-Collision-Response-Over-Time). Also the checks that keep a
// run inside the oracle's domain: no pair may be touching without separating.

#include <cstddef>
#include <string>
#include <vector>

#include "engine/space.hpp"
#include "verification/oracle/oracle.hpp"

namespace gp::verification {

/// "bodies 'A' and 'B'", for messages.
std::string describe_pair(const Space& space, BodyId a, BodyId b);

class CollisionWatch {
 public:
  /// Every pair of shapes of `space` on different bodies, one of them dynamic (kinematic and
  /// static bodies pass through each other), in shape order, except pairs of bare segments, which
  /// never touch (gp::collide). `space` must outlive the watch.
  CollisionWatch(const Space& space, const OracleOptions& options);

  /// How many root functions: one per watched pair.
  std::size_t size() const { return pairs_.size(); }

  /// The root functions: the signed distance [m] of every watched pair in state `s`. Continuous
  /// in the state (gp::signed_distance), positive while apart, so each impact is a zero crossing
  /// from above. Not reentrant: uses scratch storage.
  void distances(const MotionState& s, double* g);

  /// How long [s] the solver may integrate from state `s` (accelerations `a`) before it must stop
  /// and call again: no watched pair can move into the other by more than a tenth of their
  /// half-thicknesses in that time. A root finder only sees sign changes at the ends of steps,
  /// and a step across a whole pass-through (a ball through a bare segment, which the adaptive
  /// steps of a quadratic trajectory easily take) would show none. Infinite when nothing moves.
  /// The bound takes the accelerations as constant over the horizon; only grazing impacts, whose
  /// overlap would be shorter than the margin, can still be missed (require_apart).
  double horizon(const MotionState& s, const Accelerations& a);

  /// Resolves the impacts of the pairs whose root function crossed zero at t_c = `t` (non-zero
  /// entries of `crossed`, one per pair) in the velocities of `s`, one pair after the other, and
  /// appends one event per impulse to `log`. A pair that no longer approaches (an earlier pair's
  /// impulse separated it) gets none. Throws OracleDomainError for an impact with friction and a
  /// sliding velocity, which IM:col2D does not model.
  void resolve(double t, const std::vector<int>& crossed, MotionState& s,
               std::vector<OracleEvent>& log);

  /// Throws OracleDomainError when a pair overlaps by more than the contact tolerance, or touches
  /// (within it) without separating fast enough to get clear: a resting or persistent contact,
  /// which is not an isolated impact. `a` holds the accelerations in `s` (a pair pulled together
  /// must leave with a speed that carries it beyond the tolerance). `when` ends the message
  /// ("at the start", "after an impact").
  void require_clear(double t, const MotionState& s, const Accelerations& a,
                     const char* when) const;

  /// Throws OracleDomainError when a pair overlaps by more than the contact tolerance: an impact
  /// the root finder missed (a grazing contact that dipped below zero within one step).
  void require_apart(double t, const MotionState& s) const;

 private:
  struct Pair {
    std::size_t a;  // shape indices into Space::shapes(); the shape of body A comes first
    std::size_t b;
    double margin;  // m: how far one may move into the other between two looks (horizon())
  };

  /// A bound on the speed [m/s] and acceleration [m/s²] of every point of shape `shape`.
  double speed_bound(std::size_t shape, const MotionState& s) const;
  double acceleration_bound(std::size_t shape, const Accelerations& a) const;

  const Space& space_;
  double tolerance_;
  std::vector<Pair> pairs_;
  std::vector<double> reach_;  // m, per shape
  WorldShapes world_;          // scratch for distances()
};

}  // namespace gp::verification
