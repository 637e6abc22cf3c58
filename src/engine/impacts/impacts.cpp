#include "engine/impacts/impacts.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "engine/collision/collision_detection.hpp"
#include "engine/collision/narrowphase.hpp"
#include "engine/collision/signed_distance.hpp"
#include "engine/geometry/shape_extent.hpp"
#include "engine/geometry/transform.hpp"
#include "engine/step/step_context.hpp"
#include "gamephysics/models/dd/angular_acceleration.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/angular_velocity.hpp"
#include "gamephysics/models/dd/linear_acceleration.hpp"
#include "gamephysics/models/dd/linear_displacement.hpp"
#include "gamephysics/models/dd/linear_velocity.hpp"

namespace gp {

Vec2 Ballistic::position(BodyId body, double tau) const {
  // Each path moves at one velocity over τ: the mean on the parabola, the line's own on the line.
  const double at = shape == PathShape::kParabola ? tau / 2 : std::max(tau, 0.0);
  return dd::displaced_position(start.position[body],
                                dd::displacement_from_velocity(velocity(body, at), tau));
}

double Ballistic::angle(BodyId body, double tau) const {
  return dd::rotated_orientation(start.angle[body], turn(body, tau));
}

double Ballistic::turn(BodyId body, double tau) const {
  const double at = shape == PathShape::kParabola ? tau / 2 : std::max(tau, 0.0);
  return dd::angular_displacement_from_velocity(angular_velocity(body, at), tau);
}

namespace {

// How long the acceleration has acted on the velocity after τ [s] along a path of `shape`.
double accelerated_for(PathShape shape, double tau, double step) {
  if (shape == PathShape::kParabola || tau == 0.0) return tau;
  return tau > 0.0 ? step : -step;
}

}  // namespace

Vec2 Ballistic::velocity(BodyId body, double tau) const {
  return start.velocity[body] + dd::velocity_change_from_acceleration(
                                    acceleration.linear(body), accelerated_for(shape, tau, step));
}

double Ballistic::angular_velocity(BodyId body, double tau) const {
  return start.angular_velocity[body] +
         dd::angular_velocity_change_from_acceleration(acceleration.angular(body),
                                                       accelerated_for(shape, tau, step));
}

double closing_speed_bound(const ShapeRecord& a, const ShapeRecord& b, const Ballistic& m,
                           double h) {
  // Translation counts relative to each other (two discs falling side by side do not close),
  // turning for each body on its own.
  // A disc about its centre of mass reaches its radius, the same as reach() gives (0 + r), found
  // without a visit and a root: a rain's pairs are all such discs.
  const auto turning = [&m, h](const ShapeRecord& r) {
    return (std::abs(m.start.angular_velocity[r.body]) +
            std::abs(m.acceleration.angular(r.body)) * h) *
           (r.centred_disc() ? r.local.circle().radius : reach(r.local));
  };
  return (m.start.velocity[a.body] - m.start.velocity[b.body]).norm() +
         (m.acceleration.linear(a.body) - m.acceleration.linear(b.body)).norm() * h + turning(a) +
         turning(b);
}

namespace {

// The signed distance [m] of shapes a and b after τ [s] along `motion`.
double distance_after(const ShapeRecord& a, const ShapeRecord& b, const Ballistic& motion,
                      double tau) {
  return signed_distance(motion.placed(a, tau), motion.placed(b, tau));
}

// The shapes' first touch in (t0, h], given their signed distances d0 at t0 and d1 at h: where
// they overlap at h, bracketed for touch_time; apart at both ends, searched for here.
std::optional<Touch> first_touch(const ShapeRecord& a, const ShapeRecord& b, double d0, double d1,
                                 const Ballistic& motion, const StepWindow& window) {
  const double t0 = window.t0;
  const double h = window.h;
  if (d1 <= 0.0) return Touch{.distance_t0 = d0, .distance_h = d1};
  const auto touch_at = [d0](double tau) { return Touch{.time = tau, .distance_t0 = d0}; };
  const auto distance = [&](double tau) { return distance_after(a, b, motion, tau); };
  // Apart at both ends: they can only have met in between if they could close d0 + d1 in time.
  const double bound = closing_speed_bound(a, b, motion, h);
  if (bound * (h - t0) < d0 + d1) return std::nullopt;
  // Conservative advancement: never step further than the gap could close.
  // Down to 1e-12 m, so that the impact's position is as exact as a bracketed root's; a slow,
  // grazing approach that stops short of that within the passes still counts within 1e-9 m.
  constexpr double kTouch = 1e-12, kNear = 1e-9;  // m
  double tau = t0, d = d0;
  for (int i = 0; i < 200; ++i) {
    tau += d / bound;
    if (tau >= h) return std::nullopt;
    d = distance(tau);
    if (d <= kTouch) return touch_at(tau);
  }
  return d <= kNear ? std::optional<Touch>(touch_at(tau)) : std::nullopt;
}

}  // namespace

double touch_time(const Touch& touch, const ShapeRecord& a, const ShapeRecord& b,
                  const Ballistic& motion, const StepWindow& window) {
  if (touch.searched()) return touch.time;
  // TOMS 748 converges superlinearly on the smooth distance of ballistic motion.
  std::uintmax_t iterations = 100;
  const auto [lo, hi] = boost::math::tools::toms748_solve(
      [&](double tau) { return distance_after(a, b, motion, tau); }, window.t0, window.h,
      touch.distance_t0, touch.distance_h, boost::math::tools::eps_tolerance<double>(50),
      iterations);
  (void)hi;
  return lo;
}

std::optional<double> impact_time(const SweptShape& a, const SweptShape& b, const Ballistic& motion,
                                  const StepWindow& window, const ImpactFilter& filter) {
  const std::optional<Touch> touch = find_touch(a, b, motion, window, filter);
  if (!touch) return std::nullopt;
  return touch_time(*touch, a.shape, b.shape, motion, window);
}

std::optional<Touch> find_touch(const SweptShape& a, const SweptShape& b, const Ballistic& motion,
                                const StepWindow& window, const ImpactFilter& filter) {
  // Shapes further apart than the pair can close over the window cannot touch in it: the distance
  // changes no faster than the bound on their closing speed, so at the window's end they are
  // still apart, and the search below would find no touch. A nanometre more, far above the
  // distances' round-off, so that the result is the same with or without these tests. Their
  // boxes' gap is tested first, needing no distance computed; then the distance, which turned
  // polygons leave wider.
  constexpr double kRoundOff = 1e-9;  // m
  const double reach =
      closing_speed_bound(a.shape, b.shape, motion, window.h) * (window.h - window.t0);
  const double out_of_reach = reach + kRoundOff;
  if (a.at_t0.bounds.gap_to(b.at_t0.bounds) > out_of_reach) return std::nullopt;
  const double d0 = signed_distance(a.at_t0, b.at_t0, out_of_reach);
  if (d0 <= filter.slop) return std::nullopt;  // already in contact: the contact solver's business
  if (d0 > out_of_reach) return std::nullopt;
  const double d1 =
      signed_distance(motion.placed(a.shape, window.h), motion.placed(b.shape, window.h));
  if (d0 < filter.margin && d0 - d1 < filter.min_speed * (window.h - window.t0)) {
    return std::nullopt;
  }
  return first_touch(a.shape, b.shape, d0, d1, motion, window);
}

std::optional<double> ImpactSearch::earliest(const StepContext& c) {
  const BodyShapes& shapes = c.shapes;
  const WorldShapes& start = c.world_start;
  const double h = c.h;
  const ImpactFilter filter = impact_filter(c.settings);
  touching_.clear();
  std::optional<double> best;
  const double same_time = simultaneity(h);
  for (const ShapePair& p : c.pairs) {
    const auto tau = impact_time({shapes[p.first], start[p.first]},
                                 {shapes[p.second], start[p.second]}, *c.motion, {0.0, h}, filter);
    if (!tau) continue;
    if (!best || *tau < *best - same_time) {
      best = tau;
      touching_.assign(1, p);
    } else if (*tau <= *best + same_time) {
      touching_.push_back(p);
    }
  }
  return best;
}

void resolve_impacts(std::span<const ShapePair> pairs, StepContext& ctx, double t, MotionState& s,
                     ContactSet& contacts) {
  const BodyShapes& shapes = ctx.shapes;
  const BodyInertia& inertia = ctx.inertia;
  const Settings& settings = ctx.settings;
  std::vector<Impact>& log = ctx.impacts;
  contacts.clear();
  for (const ShapePair& p : pairs) {
    const ShapeRecord& a = shapes[p.first];
    const ShapeRecord& b = shapes[p.second];
    const ContactManifold m = collide(
        to_world(a.local, Transform(s.position[a.body], s.angle[a.body])),
        to_world(b.local, Transform(s.position[b.body], s.angle[b.body])), settings.contact_margin);
    if (m.count == 0) continue;
    append_contact(p, shapes, m, s, contacts);
  }
  const auto approach = [&s](const Contact& c, const ContactPointState& p) {
    return contact_normal_velocity(s, c, p);
  };
  if (contacts.size() == 1 && contacts[0].count() == 1 && contacts[0].friction == 0.0) {
    // One frictionless point: IM:col2D exactly.
    const Contact& c = contacts[0];
    const ContactPointState& p = contacts.points(c)[0];
    const double restitution =
        approach(c, p) < -settings.restitution_threshold ? contact_restitution(shapes, c) : 0.0;
    const double impulse = apply_collision_response(c, p, restitution, inertia, s);
    log.push_back({t, c.body_a, c.body_b, c.normal, arm_a(c, p) + s.position[c.body_a], impulse});
    return;
  }
  // An impact takes no time: no gap to close, only the restitution targets.
  prepare_contacts(contacts, shapes, inertia, s, std::numeric_limits<double>::infinity(), settings);
  // Enough passes for Gauss–Seidel to converge on a handful of simultaneous points.
  solve_velocities(contacts, inertia, 64, 0.0, s);
  apply_restitution(contacts, inertia, s);
  for (const Contact& c : contacts) {
    Vec2 point = Vec2::Zero();
    double impulse = 0.0;
    for (const ContactPointState& p : contacts.points(c)) {
      point += (arm_a(c, p) + s.position[c.body_a]) / c.count();
      impulse += p.normal_impulse;
    }
    log.push_back({t, c.body_a, c.body_b, c.normal, point, impulse});
  }
}

}  // namespace gp
