#pragma once
// FR:Determine-Collision-Response-Over-Time on positions: the displacement the contact impulses
// make over a step, and penetration removal by moving positions only, which adds no energy.

#include <cmath>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/core.hpp"
#include "engine/geometry/transform.hpp"
#include "engine/solver/contact_batches.hpp"
#include "engine/solver/contact_set.hpp"
#include "engine/threads.hpp"

namespace gp {

/// Moves and turns the bodies by the velocity changes of the contacts' accumulated impulses
/// (DD:impulseV, DD:torque) kept up for `duration` [s]: share × h for impulses that act over a
/// step of h like forces (the integrator's impulse_position_share). A negative duration takes a
/// displacement back.
void move_by_contact_impulses(const ContactSet& contacts, const BodyInertia& inertia,
                              double duration, MotionState& s);

/// Room for a vector and a number per body. The velocities before a step's impulses
/// (BodyVelocities, from the preparation to move_by_velocity_changes) and the position passes'
/// rotations (RotationCache, after) are never needed at once: the contact solver hands this room
/// from one to the other, 24 B a body less than each keeping its own.
struct BodyRoom {
  std::vector<Vec2> vectors;
  std::vector<double> numbers;
};

/// The bodies' velocities at one instant, for move_by_velocity_changes to measure against.
struct BodyVelocities {
  std::vector<Vec2> linear;     ///< m/s
  std::vector<double> angular;  ///< rad/s

  /// The velocities of `s`, kept in `room`.
  void take(const MotionState& s, BodyRoom room) {
    linear = std::move(room.vectors);
    angular = std::move(room.numbers);
    linear.assign(s.velocity.begin(), s.velocity.end());
    angular.assign(s.angular_velocity.begin(), s.angular_velocity.end());
  }
  /// Gives up the room of the velocities, which are not read again.
  BodyRoom release() { return {std::move(linear), std::move(angular)}; }
};

/// move_by_contact_impulses of every contact at once, for velocities that only the contacts'
/// impulses have changed since `before`: each body's velocity change is then the sum of its
/// contacts' J/m (DD:impulseV) and J r × n/I (DD:torque), which moves and turns it over
/// `duration` [s] (DD:linVel, DD:linDisp, DD:angVel, DD:angDisp). One visit a body instead of one a
/// contact point; a body whose velocities did not change is not written. On the threads of the
/// current task arena.
void move_by_velocity_changes(const BodyVelocities& before, double duration, MotionState& s);

/// move_by_contact_impulses for contact `c` of `contacts` alone.
void move_by_contact_impulse(const ContactSet& contacts, const Contact& c,
                             const BodyInertia& inertia, double duration, MotionState& s);

/// The rotations of bodies by an angle each (in the position passes, the angle each has turned
/// since its contacts were found): a moving body's computed only when first asked for, and after a
/// small turn updated without trigonometry (most contact points of discs need none, and position
/// passes turn bodies by tiny angles); a body that does not move has its own computed at reset.
class RotationCache {
 public:
  /// Sizes the cache for the bodies of `s` and forgets every rotation; then computes the rotation
  /// of each body the passes do not move, by `turn(body)` [rad]: contacts solved on different
  /// threads share such a body, and only read its rotation (its turn is finite: scenes and edits
  /// give a static or kinematic body only finite angles and speeds).
  template <typename Turn>
  void reset(const BodyInertia& inertia, const MotionState& s, const Turn& turn) {
    const std::size_t bodies = s.angle.size();
    angle_.resize(bodies);
    x_axis_.resize(bodies);
    for_blocks(bodies, kBodiesPerTask, bodies < kParallelBodies,
               [&](std::size_t first, std::size_t last) {
                 for (auto b = static_cast<BodyId>(first); b < last; ++b) {
                   if (movable(inertia, b)) {
                     angle_[b] = std::numeric_limits<double>::quiet_NaN();
                   } else {
                     place(b, turn(b));
                   }
                 }
               });
  }
  /// `body` was turned by `turn` [rad] to `angle` [rad]: its rotation follows, or is forgotten
  /// after a turn too large for the series of Rotation::turned.
  void turn(BodyId body, double angle, double turn) {
    if (turn == 0.0 || std::isnan(angle_[body])) return;
    if (std::abs(turn) > Rotation::kLargestSeriesTurn) {
      angle_[body] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    x_axis_[body] = rotation(body).turned(turn).x_axis();
    angle_[body] = angle;
  }
  /// `v` turned by `angle` [rad], the current angle of `body`.
  Vec2 rotate(BodyId body, double angle, const Vec2& v) {
    if (angle_[body] != angle) place(body, angle);
    return rotation(body).rotate(v);
  }
  /// The same, the rotation computed but not kept if it is not already: for threads that may
  /// read the same body at once.
  Vec2 rotate_unkept(BodyId body, double angle, const Vec2& v) const {
    return (angle_[body] == angle ? rotation(body) : rotation_by(angle)).rotate(v);
  }
  /// Gives up its room, for rotations it no longer needs (the next reset forgets them).
  BodyRoom release_room() { return {std::move(x_axis_), std::move(angle_)}; }
  /// Keeps its rotations in `room` from the next reset.
  void take_room(BodyRoom room) {
    x_axis_ = std::move(room.vectors);
    angle_ = std::move(room.numbers);
  }

 private:
  // A body that has not turned (every static one) needs no trigonometry: cos(+0) and sin(+0) are
  // 1 and +0, the identity's.
  static Rotation rotation_by(double angle) {
    return angle == 0.0 && !std::signbit(angle) ? Rotation() : Rotation(angle);
  }
  void place(BodyId body, double angle) {
    angle_[body] = angle;
    x_axis_[body] = rotation_by(angle).x_axis();
  }
  Rotation rotation(BodyId body) const { return Rotation::with_x_axis(x_axis_[body]); }
  // Bodies a thread resets at a time (a few nanoseconds each, a task about a microsecond to hand
  // out), and how many make it worth sharing out.
  static constexpr std::size_t kBodiesPerTask = 4096;
  static constexpr std::size_t kParallelBodies = 16384;
  std::vector<double> angle_;  // rad, the angle each rotation is for; NaN: none yet
  std::vector<Vec2> x_axis_;   // each rotation as its x axis: the room BodyRoom lends
};

/// How far the position passes go: at most `iterations` passes, on overlaps deeper than `slop` [m].
struct PositionLimits {
  int iterations;
  double slop;
};

/// What the position passes read of the bodies: their shapes, inertias, and their state when the
/// contacts were found (positions [m] and angles [rad], by body id).
struct ContactGeometry {
  const BodyShapes& shapes;
  const BodyInertia& inertia;
  const MotionState& detected;
};

/// Whether every point of a set of contacts, found in `geometry.detected` and none then overlapping
/// by more than `deepest` [m], surely overlaps by no more than `limits.slop` in `now`, told from
/// the bodies alone: a point's deepest points have moved into each other by at most their bodies'
/// displacements and their turns (reduced to within half a turn) times their arms, which reach no
/// farther than the shapes' reach and the contact `margin` [m]. The position passes would then
/// move nothing, and a resting pile's every point need not be read. Half the slop left is kept
/// for round-off. Never where a disc lies off its body's centre of mass.
bool surely_within_slop(double deepest, double margin, const ContactGeometry& geometry,
                        const PositionLimits& limits, const MotionState& now);

/// The position passes, with the rotations they turn bodies by kept between steps so that a step
/// does not allocate.
class PositionCorrection {
 public:
  /// At most `limits.iterations` passes that move and turn bodies apart (positions only) where the
  /// contact points overlap by more than `limits.slop` [m], removing a fifth of the excess per pass
  /// (Baumgarte's 0.2); they end after a pass that found no overlap deeper than two slops. The
  /// overlap is measured between each body's deepest point inside the other at detection, carried
  /// along as the body moved and turned from `geometry.detected`. A point whose overlap cannot
  /// have grown past the slop since, by how far its bodies moved and turned, is passed over
  /// without placing its deepest points: with the same result, as the pass would find no excess.
  void correct(const ContactSet& contacts, const ContactGeometry& geometry,
               const PositionLimits& limits, MotionState& s);
  /// correct in the order of `batches` of `contacts`, on the threads of the current task arena,
  /// a task of one-point contacts by levels (ContactBatches::Visit), its contacts between centred
  /// discs four at a time where the CPU has AVX2; the same result on any number of threads.
  void correct(const ContactBatches& batches, const ContactSet& contacts,
               const ContactGeometry& geometry, const PositionLimits& limits, MotionState& s);
  /// The room of the passes' rotations, lent out between their runs (BodyRoom).
  BodyRoom lend_room() { return rotations_.release_room(); }
  void take_room(BodyRoom room) { rotations_.take_room(std::move(room)); }

 private:
  template <typename Order>
  void correct_in(const Order& order, const ContactSet& contacts, const ContactGeometry& geometry,
                  const PositionLimits& limits, MotionState& s);

  RotationCache rotations_;
};

}  // namespace gp
