#include "engine/solver/position_passes.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <type_traits>

#include "engine/solver/disc_position_lanes.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/angular_velocity.hpp"
#include "gamephysics/models/dd/impulse.hpp"
#include "gamephysics/models/dd/linear_displacement.hpp"
#include "gamephysics/models/dd/linear_velocity.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/tm/newton_third_law.hpp"

namespace gp {

namespace {

// Bodies a task of move_by_velocity_changes moves: a body costs a few nanoseconds, handing out a
// task about a microsecond.
constexpr std::size_t kMovedBodiesPerTask = 4096;

// The angles [rad] by which displace() turned A and B.
struct Turns {
  double a;
  double b;
};

// Moves A by the positional impulse `shift` [kg·m] and B by the reaction, and turns each by the
// moment of its share about its centre of mass [kg·m²] (DD:impulseV, DD:torque,
// TM:NewtonThirdLawMot applied to displacements instead of velocities). Always inlined: called
// out of line, it costs the position passes an eighth more instructions (callgrind, rain1000).
[[gnu::always_inline]] inline Turns displace(const BodyInertia& m, const Contact& c,
                                             const Vec2& shift, double moment_a, double moment_b,
                                             MotionState& s) {
  const Vec2 back = tm::reaction_force(shift);
  const Turns turns{moment_a * m.inverse_moment[c.body_a], moment_b * m.inverse_moment[c.body_b]};
  // Only movable bodies are written: a static or kinematic body may be in contacts solved on
  // other threads at the same time, and does not move.
  if (movable(m, c.body_a)) {
    s.position[c.body_a] += dd::velocity_change_from_impulse(shift, m.inverse_mass[c.body_a]);
    s.angle[c.body_a] = dd::rotated_orientation(s.angle[c.body_a], turns.a);
  }
  if (movable(m, c.body_b)) {
    s.position[c.body_b] += dd::velocity_change_from_impulse(back, m.inverse_mass[c.body_b]);
    s.angle[c.body_b] = dd::rotated_orientation(s.angle[c.body_b], turns.b);
  }
  return turns;
}

// A bound [m] on the length of the arm the position passes place for one body's deepest point,
// of kind `kind`, as it turns with the body, which is +∞ for an offset disc's: the arm at
// detection, t_arm n − n_arm t (arm_from, with that body's `tangent_arm` and `normal_arm`), less
// half the depth along n; none for a centred disc's, which stays along the normal whichever way
// the disc turns.
double turning_arm_bound(AnchorKind kind, double tangent_arm, double normal_arm, float depth) {
  switch (kind) {
    case AnchorKind::kCentredDisc:
      return 0.0;
    case AnchorKind::kFixed:
      return std::abs(tangent_arm) + std::abs(normal_arm) + std::abs(0.5 * depth);
    case AnchorKind::kOffsetDisc:
      break;
  }
  return std::numeric_limits<double>::infinity();
}

// The 1-norm [m] of `v`, which is at least its length.
double extent(const Vec2& v) {
  return std::abs(v.x()) + std::abs(v.y());
}

// The 1-norm [m] of body b's displacement from `detected` to `now`.
double travel(const MotionState& now, const MotionState& detected, BodyId b) {
  return extent(now.position[b] - detected.position[b]);
}

// How far a contact's two bodies moved in `now` since `detected`, for telling the points that
// surely overlap by no more than the slop: at detection the separation of a point's deepest points
// was −depth, and since then it has fallen by no more than those points moved, each by at most
// its body's displacement plus its turn times its arm, |(R(φ) − I) r| = 2 |sin(φ / 2)| |r| ≤
// |φ| |r|.
class MovedSinceDetection {
 public:
  MovedSinceDetection(const Contact& c, const MotionState& now, const MotionState& detected)
      : centres_(travel(now, detected, c.body_a) + travel(now, detected, c.body_b)),
        turn_a_(std::abs(now.angle[c.body_a] - detected.angle[c.body_a])),
        turn_b_(std::abs(now.angle[c.body_b] - detected.angle[c.body_b])),
        scale_(1.0 + extent(now.position[c.body_a]) + extent(now.position[c.body_b])) {}

  // Whether point `p`, which the slop leaves `room` [m] to overlap more, surely still has room.
  // The margin covers the round-off of the separation a pass computes (about 1e-16 of the
  // positions and arms) and of its rotations (1e-13 rad) many times over.
  [[gnu::always_inline]] bool within_slop(const ContactPointState& p, double room) const {
    constexpr double kRoundOff = 1e-12;
    const double left = room - centres_ - kRoundOff * scale_;
    if (left < 0.0) return false;
    const double arm_a = turning_arm_bound(p.anchor_a, p.tangent_arm_a, p.normal_arm_a, p.depth);
    const double arm_b = turning_arm_bound(p.anchor_b, p.tangent_arm_b, p.normal_arm_b, p.depth);
    return left - (turn_a_ + kRoundOff) * arm_a - (turn_b_ + kRoundOff) * arm_b >= 0.0;
  }

 private:
  double centres_;  // m, both bodies' displacements
  double turn_a_;   // rad
  double turn_b_;
  double scale_;  // m, of the positions, for the round-off
};

}  // namespace

void move_by_contact_impulse(const ContactSet& contacts, const Contact& c,
                             const BodyInertia& inertia, double duration, MotionState& s) {
  for (const ContactPointState& p : contacts.points(c)) {
    const double normal = duration * p.normal_impulse;
    const double tangent = duration * p.tangent_impulse;
    // The moment of j_n n + j_t t at arm r is j_n (r × n) + j_t (r × t) (DD:torque).
    displace(inertia, c, normal * c.normal + tangent * contact_tangent(c.normal),
             normal * p.normal_arm_a + tangent * p.tangent_arm_a,
             -(normal * p.normal_arm_b + tangent * p.tangent_arm_b), s);
  }
}

void move_by_contact_impulses(const ContactSet& contacts, const BodyInertia& inertia,
                              double duration, MotionState& s) {
  for (const Contact& c : contacts) move_by_contact_impulse(contacts, c, inertia, duration, s);
}

void move_by_velocity_changes(const BodyVelocities& before, double duration, MotionState& s) {
  const auto move_range = [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; ++b) {
      const Vec2 change = s.velocity[b] - before.linear[b];
      const double angular_change = s.angular_velocity[b] - before.angular[b];
      if (change.x() == 0.0 && change.y() == 0.0 && angular_change == 0.0) continue;
      s.position[b] =
          dd::displaced_position(s.position[b], dd::displacement_from_velocity(change, duration));
      s.angle[b] = dd::rotated_orientation(
          s.angle[b], dd::angular_displacement_from_velocity(angular_change, duration));
    }
  };
  const std::size_t count = s.velocity.size();
  for_blocks(count, kMovedBodiesPerTask, count < 2 * kMovedBodiesPerTask, move_range);
}

namespace {

// The arm [m], now, from a body's centre of mass to its deepest point inside the other body at
// detection, carried along as the body moved and turned since. `deepest` gives that arm at
// detection (rebuilt only where needed), `outward` the unit normal away from the body, `reach` the
// arm's component along it, and `turned` turns a vector with the body.
template <typename Arm, typename Turned>
Vec2 anchor_arm(AnchorKind kind, const ShapeRecord& shape, const Arm& deepest, const Vec2& outward,
                double reach, const Turned& turned) {
  switch (kind) {
    case AnchorKind::kCentredDisc:
      // Whichever way the disc turns, its deepest point is its radius away along the normal.
      return reach * outward;
    case AnchorKind::kOffsetDisc: {
      const double radius = shape.local.circle().radius;
      return turned(deepest() - radius * outward) + radius * outward;
    }
    case AnchorKind::kFixed:
      break;
  }
  return turned(deepest());
}

// One position pass over a colour's or a level's contacts, which share no movable body: those
// between two centred discs four at a time (correct_centred_discs, only where four_lanes()), the
// others by `solve`. Returns 1 if one overlapped by more than two slops, else 0, as `solve` does.
template <typename Solve>
double correct_independent(const ContactSet& contacts, std::span<const std::uint32_t> independent,
                           const Solve& solve, const DiscPositionInput& in, MotionState& s) {
  const auto centred = [&](std::uint32_t i) {
    const Contact& c = contacts[i];
    return c.count() == 1 && centred_discs(contacts.points(c)[0]);
  };
  double deep = 0.0;
  // Runs of contacts between centred discs, each handed over where it lies, and the others.
  for (std::size_t done = 0; done < independent.size();) {
    std::size_t run = 0;
    while (done + run < independent.size() && centred(independent[done + run])) ++run;
    if (run > 0) {
      if (correct_centred_discs(contacts, independent.subspan(done, run), in, s)) deep = 1.0;
      done += run;
      continue;
    }
    deep = std::max(deep, solve(independent[done]));
    ++done;
  }
  return deep;
}

// Where a position pass finds a contact point: the separation [m] along the normal, now, of
// each body's deepest point inside the other at detection, the arms [m] from the bodies' centres
// of mass to those points, and the excess overlap it removes (0: none, and then nothing else is
// set).
struct PointOverlap {
  double excess = 0.0;
  double separation = 0.0;
  Vec2 arm_a;
  Vec2 arm_b;
};

// Contacts a thread scans at a time for an excess overlap: a few nanoseconds each, a task about
// a microsecond to hand out.
constexpr std::size_t kScannedContactsPerTask = 4096;

// The larger of a and b, NaN if either is: a NaN must not pass a bound unseen.
double larger(double a, double b) {
  return b > a || std::isnan(b) ? b : a;
}

}  // namespace

bool surely_within_slop(double deepest, double margin, const ContactGeometry& geometry,
                        const PositionLimits& limits, const MotionState& now) {
  const BodyShapes& shapes = geometry.shapes;
  const MotionState& detected = geometry.detected;
  if (shapes.any_offset_disc() || !(deepest < limits.slop)) return false;
  // The most any body moved (the 1-norm, at least the length) and turned since detection, and the
  // farthest from the origin any is (the scale of the round-off).
  struct Found {
    double travel = 0.0;  // m
    double turn = 0.0;    // rad
    double extent = 0.0;  // m
  };
  const std::size_t count = now.position.size();
  const Found found = reduce_blocks(
      count, kMovedBodiesPerTask, count < 2 * kMovedBodiesPerTask, Found{},
      [&](std::size_t first, std::size_t last, Found f) {
        for (std::size_t b = first; b < last; ++b) {
          f.travel = larger(f.travel, travel(now, detected, b));
          f.turn = larger(f.turn, std::abs(within_half_turn(now.angle[b] - detected.angle[b])));
          f.extent = larger(f.extent, extent(now.position[b]));
        }
        return f;
      },
      [](const Found& x, const Found& y) {
        return Found{larger(x.travel, y.travel), larger(x.turn, y.turn),
                     larger(x.extent, y.extent)};
      });
  // A deepest point's arm: to the contact point, midway between the shapes' surfaces (within the
  // shape's reach and half the margin or the depth), and half the depth along the normal. Only
  // dynamic and kinematic bodies turn, whose shapes move.
  const double beyond = std::max(deepest, margin);
  const double turning_arm = shapes.moving_reach() + beyond;
  const double any_arm = shapes.reach() + beyond;
  constexpr double kRoundOff = 1e-12;  // as MovedSinceDetection's, relative to the scales
  const double moved = 2.0 * found.travel + 2.0 * found.turn * turning_arm +
                       kRoundOff * (1.0 + 2.0 * found.extent + 2.0 * any_arm);
  return moved <= 0.5 * (limits.slop - deepest);
}

template <typename Order>
void PositionCorrection::correct_in(const Order& order, const ContactSet& contacts,
                                    const ContactGeometry& geometry, const PositionLimits& limits,
                                    MotionState& s) {
  const BodyShapes& shapes = geometry.shapes;
  const BodyInertia& inertia = geometry.inertia;
  const MotionState& detected = geometry.detected;
  RotationCache& rotations = rotations_;
  const double slop = limits.slop;
  int iterations = limits.iterations;
  constexpr double kBaumgarte = 0.2;      // fraction of the excess overlap removed per pass
  constexpr double kMaxCorrection = 0.2;  // m per pass, so a deep overlap is not flung apart
  const auto turn = [&](BodyId b) { return s.angle[b] - detected.angle[b]; };
  rotations.reset(inertia, s, turn);
  // `moved` is how far c's bodies moved, `turned_with(b)` turns a vector with body b since
  // detection.
  const auto overlap_at = [&](const Contact& c, const ContactPointState& p,
                              const MovedSinceDetection& moved, const auto& turned_with) {
    PointOverlap o;
    // Every point of a pile at rest is passed over here, where placing its anchors took 12% of
    // the pile's step.
    if (const double room = slop - static_cast<double>(p.depth);
        room > 0.0 && moved.within_slop(p, room)) {
      return o;
    }
    // Each body's deepest point inside the other at detection, half the depth from the contact
    // point.
    const double half_depth = 0.5 * p.depth;
    o.arm_a = anchor_arm(
        p.anchor_a, shapes[c.shape_a],
        [&]() -> Vec2 { return gp::arm_a(c, p) - half_depth * c.normal; }, -c.normal,
        half_depth - p.tangent_arm_a, turned_with(c.body_a));
    o.arm_b = anchor_arm(
        p.anchor_b, shapes[c.shape_b],
        [&]() -> Vec2 { return gp::arm_b(c, p) + half_depth * c.normal; }, c.normal,
        p.tangent_arm_b + half_depth, turned_with(c.body_b));
    o.separation = (s.position[c.body_a] + o.arm_a - s.position[c.body_b] - o.arm_b).dot(c.normal);
    o.excess = std::clamp(kBaumgarte * (o.separation + slop), -kMaxCorrection, 0.0);
    return o;
  };
  // A pass moves no body when every point is within the slop (a resting pile's at nearly every
  // step), and that ends the passes. Told by a scan of the contacts in the order they are kept,
  // which reads them one after the other rather than by colours or levels; it reads the rotations
  // without keeping them, as contacts scanned on different threads at once may share a body.
  const auto unkept_turn = [&](BodyId b) {
    return [&rotations, &turn, b](const Vec2& v) { return rotations.rotate_unkept(b, turn(b), v); };
  };
  const auto any_excess = [&](std::size_t first, std::size_t last, bool any) {
    for (std::size_t i = first; i < last && !any; ++i) {
      const Contact& c = contacts[i];
      const MovedSinceDetection moved(c, s, detected);
      for (const ContactPointState& p : contacts.points(c)) {
        any = any || overlap_at(c, p, moved, unkept_turn).excess != 0.0;
      }
    }
    return any;
  };
  if (!reduce_blocks(contacts.size(), kScannedContactsPerTask,
                     contacts.size() < 2 * kScannedContactsPerTask, false, any_excess,
                     std::logical_or<>())) {
    return;
  }
  const auto kept_turn = [&](BodyId b) {
    return [&rotations, &turn, b](const Vec2& v) { return rotations.rotate(b, turn(b), v); };
  };
  const auto solve = [&](std::uint32_t i) {
    const Contact& c = contacts[i];
    bool contact_deep = false;
    for (const ContactPointState& p : contacts.points(c)) {
      // Anew at each point: the last point's correction moved the bodies.
      const PointOverlap o = overlap_at(c, p, MovedSinceDetection(c, s, detected), kept_turn);
      if (o.excess == 0.0) continue;
      contact_deep = contact_deep || o.separation < -2.0 * slop;
      // The impulses' effective mass, applied to a displacement instead of a velocity; set up
      // for the step's arms, which the small turns of these passes barely change.
      const Vec2 shift = -o.excess * p.normal_mass * c.normal;
      // A push along the normal through a disc's centre does not turn it: zero exactly, not
      // by round-off, so that nothing turns it and its rotation is not looked up.
      const auto moment = [&](AnchorKind kind, const Vec2& arm, const Vec2& push) {
        return kind == AnchorKind::kCentredDisc ? 0.0 : dd::torque(arm, push);
      };
      const Turns turns = displace(inertia, c, shift, moment(p.anchor_a, o.arm_a, shift),
                                   moment(p.anchor_b, o.arm_b, tm::reaction_force(shift)), s);
      rotations.turn(c.body_a, turn(c.body_a), turns.a);
      rotations.turn(c.body_b, turn(c.body_b), turns.b);
    }
    return contact_deep ? 1.0 : 0.0;
  };
  // Passes end after one that found no point overlapping by more than two slops: what is left
  // is within the resting overlap's own scale, and a pass there moves bodies by mere microns.
  for (bool deep = true; deep && iterations-- > 0;) {
    if constexpr (std::is_same_v<Order, ContactBatches>) {
      if (four_lanes()) {
        deep = 0.0 !=
               order.run(
                   solve,
                   [&](std::span<const std::uint32_t> independent) {
                     return correct_independent(contacts, independent, solve, {inertia, slop}, s);
                   },
                   ContactBatches::Visit{.by_levels = true});
        continue;
      }
    }
    deep = 0.0 != order.run(solve);
  }
}

void PositionCorrection::correct(const ContactSet& contacts, const ContactGeometry& geometry,
                                 const PositionLimits& limits, MotionState& s) {
  correct_in(ContactsInOrder(contacts), contacts, geometry, limits, s);
}

void PositionCorrection::correct(const ContactBatches& batches, const ContactSet& contacts,
                                 const ContactGeometry& geometry, const PositionLimits& limits,
                                 MotionState& s) {
  correct_in(batches, contacts, geometry, limits, s);
}

}  // namespace gp
