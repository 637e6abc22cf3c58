#include "verification/oracle/collision_watch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "engine/collision/narrowphase.hpp"
#include "engine/collision/signed_distance.hpp"
#include "engine/geometry/shape_extent.hpp"
#include "engine/geometry/transform.hpp"
#include "gamephysics/models/dd/chasles_theorem.hpp"
#include "gamephysics/models/dd/relative_velocity.hpp"
#include "gamephysics/models/im/collision_response.hpp"

namespace gp::verification {

namespace {

// A relative speed below this fraction of the speeds of the two contact points is rounding, not
// motion: a perfectly inelastic impact leaves ~1e-16 of it, a separating pair far more.
constexpr double kSpeedRatio = 1e-9;

// The share of two shapes' half-thicknesses a pair may move into each other between two looks
// of the root finder. Smaller costs a few more stops near contacts; larger lets more grazing
// impacts (whose overlap is shorter) slip between two looks.
constexpr double kMarginShare = 0.1;

WorldShape placed(const ShapeRecord& r, const MotionState& s) {
  return to_world(r.local, Transform(s.position[r.body], s.angle[r.body]));
}

// Where and how two touching shapes meet.
struct PairContact {
  Vec2 normal;  // unit, from B towards A
  Vec2 point;   // m, world
  Vec2 arm_a;   // m, from A's centre of mass to the point
  Vec2 arm_b;
  Vec2 relative_velocity;  // m/s: of A's material point at the contact relative to B's
  double speed_scale;      // m/s: |v_AP| + |v_BP|, what rounding in relative_velocity scales with
};

// gp::collide's contact, within `margin` [m]; one point, or the midpoint of two: an edge landing
// flat on an edge touches along a segment, and IM:col2D at its midpoint is the impulse that
// neither turns a symmetric body nor prefers one end.
std::optional<PairContact> contact_of(const ShapeRecord& a, const ShapeRecord& b,
                                      const MotionState& s, double margin) {
  const ContactManifold m = collide(placed(a, s), placed(b, s), margin);
  if (m.count == 0) return std::nullopt;
  Vec2 point = Vec2::Zero();
  for (int k = 0; k < m.count; ++k) point += m.points[k].position / m.count;
  PairContact c{m.normal,     point, point - s.position[a.body], point - s.position[b.body],
                Vec2::Zero(), 0.0};
  const Vec2 va = dd::point_velocity(s.velocity[a.body], s.angular_velocity[a.body], c.arm_a);
  const Vec2 vb = dd::point_velocity(s.velocity[b.body], s.angular_velocity[b.body], c.arm_b);
  c.relative_velocity = dd::relative_velocity(va, vb);
  c.speed_scale = va.norm() + vb.norm();
  return c;
}

// Acceleration of a body's material point at `arm` [m/s²]: a + α × r − ω² r.
Vec2 point_acceleration(BodyId body, const Vec2& arm, const MotionState& s,
                        const Accelerations& a) {
  const double omega = s.angular_velocity[body];
  return a.linear[body] + cross(a.angular[body], arm) - omega * omega * arm;
}

}  // namespace

std::string describe_pair(const Space& space, BodyId a, BodyId b) {
  return "bodies '" + std::string(space.name(a)) + "' and '" + std::string(space.name(b)) + "'";
}

CollisionWatch::CollisionWatch(const Space& space, const OracleOptions& options)
    : space_(space), tolerance_(options.contact_tolerance) {
  const BodyShapes& shapes = space.shapes();
  for (std::size_t i = 0; i < shapes.size(); ++i) reach_.push_back(reach(shapes[i].local));
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = i + 1; j < shapes.size(); ++j) {
      const BodyId a = shapes[i].body, b = shapes[j].body;
      const bool one_dynamic =
          space.type(a) == BodyType::Dynamic || space.type(b) == BodyType::Dynamic;
      const double margin =
          kMarginShare * (half_thickness(shapes[i].local) + half_thickness(shapes[j].local));
      if (a != b && one_dynamic && margin > 0.0) pairs_.push_back({i, j, margin});
    }
  }
}

double CollisionWatch::speed_bound(std::size_t shape, const MotionState& s) const {
  const BodyId j = space_.shapes()[shape].body;
  return s.velocity[j].norm() + std::abs(s.angular_velocity[j]) * reach_[shape];
}

double CollisionWatch::acceleration_bound(std::size_t shape, const Accelerations& a) const {
  const BodyId j = space_.shapes()[shape].body;
  return a.linear[j].norm() + std::abs(a.angular[j]) * reach_[shape];
}

double CollisionWatch::horizon(const MotionState& s, const Accelerations& a) {
  space_.shapes().place(s.position, s.angle, world_);
  double shortest = std::numeric_limits<double>::infinity();
  for (const Pair& p : pairs_) {
    const double speed = speed_bound(p.a, s) + speed_bound(p.b, s);
    const double acceleration = acceleration_bound(p.a, a) + acceleration_bound(p.b, a);
    if (speed == 0.0 && acceleration == 0.0) continue;
    // The time to cover the gap plus the margin at speed + acceleration·t: the positive root of
    // speed·t + acceleration·t²/2 = travel, written so as not to cancel when acceleration is 0.
    const double travel = std::max(signed_distance(world_[p.a], world_[p.b]), 0.0) + p.margin;
    shortest = std::min(
        shortest, 2.0 * travel / (speed + std::sqrt(speed * speed + 2.0 * acceleration * travel)));
  }
  return shortest;
}

void CollisionWatch::distances(const MotionState& s, double* g) {
  space_.shapes().place(s.position, s.angle, world_);
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    g[k] = signed_distance(world_[pairs_[k].a], world_[pairs_[k].b]);
  }
}

void CollisionWatch::resolve(double t, const std::vector<int>& crossed, MotionState& s,
                             std::vector<OracleEvent>& log) {
  const BodyShapes& shapes = space_.shapes();
  const BodyInertia& inertia = space_.inertia();
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    if (crossed[k] == 0) continue;
    const ShapeRecord& a = shapes[pairs_[k].a];
    const ShapeRecord& b = shapes[pairs_[k].b];
    const auto c = contact_of(a, b, s, tolerance_);
    if (!c || c->relative_velocity.dot(c->normal) >= 0.0) continue;
    const Vec2 sliding = c->relative_velocity - c->relative_velocity.dot(c->normal) * c->normal;
    if (a.friction * b.friction > 0.0 && sliding.norm() > kSpeedRatio * c->speed_scale) {
      throw OracleDomainError(describe_pair(space_, a.body, b.body) +
                                  " collide with friction while sliding; the oracle resolves "
                                  "frictionless impacts (IM:col2D) only",
                              t);
    }
    const im::CollidingBody body_a{inertia.inverse_mass[a.body], inertia.inverse_moment[a.body],
                                   s.velocity[a.body], s.angular_velocity[a.body], c->arm_a};
    const im::CollidingBody body_b{inertia.inverse_mass[b.body], inertia.inverse_moment[b.body],
                                   s.velocity[b.body], s.angular_velocity[b.body], c->arm_b};
    const auto r =
        im::collision_response(body_a, body_b, c->normal, std::max(a.restitution, b.restitution));
    s.velocity[a.body] = r.velocity_a;
    s.angular_velocity[a.body] = r.angular_velocity_a;
    s.velocity[b.body] = r.velocity_b;
    s.angular_velocity[b.body] = r.angular_velocity_b;
    log.push_back({t, a.body, b.body, c->normal, c->point, r.impulse});
  }
}

void CollisionWatch::require_clear(double t, const MotionState& s, const Accelerations& a,
                                   const char* when) const {
  require_apart(t, s);
  const BodyShapes& shapes = space_.shapes();
  for (const Pair& p : pairs_) {
    const ShapeRecord& ra = shapes[p.a];
    const ShapeRecord& rb = shapes[p.b];
    if (signed_distance(placed(ra, s), placed(rb, s)) > tolerance_) continue;
    const auto c = contact_of(ra, rb, s, tolerance_);
    if (!c) continue;
    // > 0: separating; + 0.0 turns a −0 into 0 for the message.
    const double speed = c->relative_velocity.dot(c->normal) + 0.0;
    // The gap a pair opens before a closing acceleration brings it back is v²/(2a): it must
    // exceed the tolerance for the next impact to be a clean zero crossing.
    const double closing =
        -(point_acceleration(ra.body, c->arm_a, s, a) - point_acceleration(rb.body, c->arm_b, s, a))
             .dot(c->normal);
    const bool separates = speed > kSpeedRatio * c->speed_scale &&
                           speed * speed > 2.0 * std::max(closing, 0.0) * tolerance_;
    if (!separates) {
      throw OracleDomainError(describe_pair(space_, ra.body, rb.body) + " are in contact " + when +
                                  " and do not separate (normal speed " + message_number(speed) +
                                  " m/s): resting or persistent contact is outside the "
                                  "oracle's domain (isolated impacts only)",
                              t);
    }
  }
}

void CollisionWatch::require_apart(double t, const MotionState& s) const {
  const BodyShapes& shapes = space_.shapes();
  for (const Pair& p : pairs_) {
    const ShapeRecord& a = shapes[p.a];
    const ShapeRecord& b = shapes[p.b];
    const double d = signed_distance(placed(a, s), placed(b, s));
    if (d < -tolerance_) {
      throw OracleDomainError(describe_pair(space_, a.body, b.body) + " overlap by " +
                                  message_number(-d) +
                                  " m: the oracle needs them apart (or an impact it could "
                                  "not locate: a grazing contact)",
                              t);
    }
  }
}

}  // namespace gp::verification
