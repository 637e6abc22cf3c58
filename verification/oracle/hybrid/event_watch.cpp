#include "verification/oracle/hybrid/event_watch.hpp"
#include "verification/oracle/geometry/contact_geometry.hpp"
#include "verification/oracle/geometry/placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gp::oracle {

namespace {

// The share of two hulls' half-thicknesses a pair may move into each other between two looks
// of the root finder: smaller costs more stops near contacts, larger lets grazing impacts slip by.
constexpr double kMarginShare = 0.1;

// m: how deep two hulls are into each other when their approach is an event. Not zero, so that
// a pair that touched at an event and let go, its distance 0 up to round-off (1e-16 m), is not
// found touching again and again; small enough that an impact is found at most 1e-12 m / v late
// (1e-8 s at the rest speed of 1e-4 m/s, below which arrivals do not bounce anyway).
constexpr double kApproachDepth = 1e-12;

// m: the same for a pair released at rest (EventWatch::release), until it is this far apart. Its
// distance grows as t² or t³ from zero and is found negative on the solver's error (1e-12 m)
// again and again, each time an event that changes nothing; a real return of such a pair is
// found at most this deep, a tenth of the contact tolerance (1e-9 m).
constexpr double kReleaseDepth = 1e-10;

// The share of the bodies' weight (their mass times g, or times 1 m/s² without gravity) below
// which a contact's force counts as zero: a contact that holds with no force (two bodies falling
// together) or friction exactly at its bound would otherwise chatter on round-off. A lift-off is
// found when the force reaches −floor, at most floor/ḟ late.
constexpr double kForceShare = 1e-10;

// m: the distance from the hull's centroid to its nearest side, plus its rounding.
double half_thickness(const Hull& h) {
  if (h.vertices.size() < 3) return h.radius;
  Vec2 centroid = Vec2::Zero();
  for (const Vec2& v : h.vertices) centroid += v / static_cast<double>(h.vertices.size());
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < h.vertices.size(); ++i) {
    const Vec2 n = edge_normal(h.vertices, static_cast<int>(i));
    nearest = std::min(nearest, (h.vertices[i] - centroid).dot(n));
  }
  return nearest + h.radius;
}

// The kinematics of `c` if its first body's vertex were vertex `v` of its hull instead.
ContactKinematics at_vertex(const World& world, ActiveContact c, int v, std::span<const Motion> m) {
  c.vertex = world.bodies[c.first].hulls[c.first_hull].vertices[static_cast<std::size_t>(v)];
  return contact_kinematics(c, m[c.first], m[c.second]);
}

// sin of the angle by which `normal` (outward at vertex v of `hull`, world) is inside the
// vertex's normal cone, on side 0 (the edge before v) or 1 (the edge from v).
double inside_corner(const Hull& hull, int v, const Motion& body, const Vec2& normal, int side) {
  const auto n = static_cast<int>(hull.vertices.size());
  const Vec2 local =
      side == 0 ? edge_normal(hull.vertices, (v + n - 1) % n) : edge_normal(hull.vertices, v);
  const double c = std::cos(body.angle);
  const double s = std::sin(body.angle);
  const Vec2 edge(c * local.x() - s * local.y(), s * local.x() + c * local.y());
  return side == 0 ? cross(edge, normal) : cross(normal, edge);
}

// Whether vertex `v` of the first body of contact `c` projects onto the contact's edge at
// `motions`: only such a vertex can land on it; one beside the edge's extent would cross its
// line without touching it.
bool faces_edge(const World& world, const ActiveContact& c, int v,
                std::span<const Motion> motions) {
  const ContactKinematics k = at_vertex(world, c, v, motions);
  return k.along_edge >= 0.0 && k.along_edge <= k.edge_length;
}

}  // namespace

EventWatch::EventWatch(const World& world, double end_tolerance, double slip_floor)
    : world_(world), end_tolerance_(end_tolerance), slip_floor_(slip_floor) {
  for (std::size_t a = 0; a < world.bodies.size(); ++a) {
    for (std::size_t b = a + 1; b < world.bodies.size(); ++b) {
      if (world.bodies[a].type != BodyType::Dynamic && world.bodies[b].type != BodyType::Dynamic) {
        continue;
      }
      for (std::size_t i = 0; i < world.bodies[a].hulls.size(); ++i) {
        for (std::size_t j = 0; j < world.bodies[b].hulls.size(); ++j) {
          const Hull& ha = world.bodies[a].hulls[i];
          const Hull& hb = world.bodies[b].hulls[j];
          const double margin = kMarginShare * (half_thickness(ha) + half_thickness(hb));
          if (margin <= 0.0) continue;
          pairs_.push_back({a, i, b, j, margin});
          reach_.push_back(reach(ha));
          reach_.push_back(reach(hb));
        }
      }
    }
  }
  in_contact_.assign(pairs_.size(), false);
  released_.assign(pairs_.size(), false);
  double mass = 0.0;
  for (const RigidBody& b : world.bodies) mass += b.type == BodyType::Dynamic ? b.mass : 0.0;
  force_floor_ = kForceShare * mass * std::max(world.gravity.norm(), 1.0);
}

void EventWatch::arm(std::span<const ActiveContact> contacts, std::span<const Motion> motions) {
  roots_.clear();
  std::fill(in_contact_.begin(), in_contact_.end(), false);
  for (const ActiveContact& c : contacts) in_contact_[c.pair] = true;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    if (released_[p] && (in_contact_[p] || distance(p, motions) > kReleaseDepth)) {
      released_[p] = false;
    }
    if (!in_contact_[p]) roots_.push_back({RootKind::Approach, p, 0});
  }
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ActiveContact& c = contacts[i];
    roots_.push_back({RootKind::LiftOff, i, 0});
    if (c.mode == ContactMode::Sticking) {
      roots_.push_back({RootKind::StickLimit, i, 0});
      roots_.push_back({RootKind::StickLimit, i, 1});
    } else if (c.mode == ContactMode::Sliding) {
      roots_.push_back({RootKind::SlipStop, i, 0});
    }
    if (c.on_edge) {
      // A vertex at an end of its edge (a box on another, corner on corner) is watched leaving
      // it only once past it by the tolerance (sides 2, 3): from zero the root function would
      // chatter on round-off, and unwatched the vertex would ride the edge's line beyond it.
      const ContactKinematics k = contact_kinematics(c, motions[c.first], motions[c.second]);
      roots_.push_back({RootKind::OffEdge, i, k.along_edge > end_tolerance_ ? 0 : 2});
      roots_.push_back(
          {RootKind::OffEdge, i, k.edge_length - k.along_edge > end_tolerance_ ? 1 : 3});
      const auto& vertices = world_.bodies[c.first].hulls[c.first_hull].vertices;
      for (int v = 0; v < static_cast<int>(vertices.size()); ++v) {
        const bool active = std::any_of(contacts.begin(), contacts.end(), [&](const auto& o) {
          return o.pair == c.pair && o.first == c.first && o.on_edge &&
                 o.second_feature == c.second_feature && o.first_vertex == v;
        });
        if (!active && faces_edge(world_, c, v, motions)) {
          roots_.push_back({RootKind::Landing, i, v});
        }
      }
    } else {
      // Corner on corner: the normal must stay inside both corners' cones, so both are watched.
      const bool second_corner = world_.bodies[c.second].hulls[c.second_hull].vertices.size() >= 2;
      const bool first_corner = world_.bodies[c.first].hulls[c.first_hull].vertices.size() >= 2;
      for (int side = 0; side < 2; ++side) {
        if (second_corner) roots_.push_back({RootKind::OffCorner, i, side});
        if (first_corner) roots_.push_back({RootKind::OffCorner, i, 2 + side});
      }
    }
  }
}

void EventWatch::release(std::size_t p) {
  released_[p] = true;
}

double EventWatch::distance(std::size_t p, std::span<const Motion> motions) const {
  const HullPair& pair = pairs_[p];
  return signed_distance(
      world_.bodies[pair.body_a].hulls[pair.hull_a], pose_of(motions[pair.body_a]),
      world_.bodies[pair.body_b].hulls[pair.hull_b], pose_of(motions[pair.body_b]));
}

void EventWatch::evaluate(const Snapshot& s, std::span<const ActiveContact> contacts,
                          double* g) const {
  for (std::size_t r = 0; r < roots_.size(); ++r) {
    const Root& root = roots_[r];
    if (root.kind == RootKind::Approach) {
      g[r] = distance(root.index, s.motions) +
             (released_[root.index] ? kReleaseDepth : kApproachDepth);
      continue;
    }
    const ActiveContact& c = contacts[root.index];
    const ContactKinematics& k = s.kinematics[root.index];
    const ContactForce& f = s.forces[root.index];
    switch (root.kind) {
      case RootKind::LiftOff:
        g[r] = f.normal + force_floor_;
        break;
      case RootKind::StickLimit:
        g[r] = c.friction * f.normal - (root.detail == 0 ? f.tangent : -f.tangent) + force_floor_;
        break;
      case RootKind::SlipStop:
        // Half the floor: a slip stopped there is below it, so the modes are chosen afresh.
        g[r] = c.slip_sign * k.slip + 0.5 * slip_floor_;
        break;
      case RootKind::OffEdge:
        g[r] = (root.detail % 2 == 0 ? k.along_edge : k.edge_length - k.along_edge) +
               (root.detail >= 2 ? end_tolerance_ : 0.0);
        break;
      case RootKind::Landing:
        g[r] = at_vertex(world_, c, root.detail, s.motions).gap;
        break;
      case RootKind::OffCorner: {
        // Sides 0, 1 are of the second's corner (its outward normal is n), 2, 3 of the first's
        // (−n).
        g[r] = root.detail < 2
                   ? inside_corner(world_.bodies[c.second].hulls[c.second_hull], c.second_feature,
                                   s.motions[c.second], k.normal, root.detail)
                   : inside_corner(world_.bodies[c.first].hulls[c.first_hull], c.first_vertex,
                                   s.motions[c.first], -k.normal, root.detail - 2);
        break;
      }
      case RootKind::Approach:
        break;
    }
  }
}

double EventWatch::horizon(const Snapshot& s) const {
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    if (in_contact_[p]) continue;
    const HullPair& pair = pairs_[p];
    const auto bound = [&](std::size_t body, double r, bool acceleration) {
      const Motion& m = s.motions[body];
      return acceleration
                 ? s.linear[body].norm() +
                       (std::abs(s.angular[body]) + m.angular_velocity * m.angular_velocity) * r
                 : m.velocity.norm() + std::abs(m.angular_velocity) * r;
    };
    const double ra = reach_[2 * p];
    const double rb = reach_[2 * p + 1];
    const double speed = bound(pair.body_a, ra, false) + bound(pair.body_b, rb, false);
    const double acceleration = bound(pair.body_a, ra, true) + bound(pair.body_b, rb, true);
    if (speed == 0.0 && acceleration == 0.0) continue;
    // The time to cover the gap plus the margin at speed + acceleration·t: the positive root of
    // speed·t + acceleration·t²/2 = travel, written so as not to cancel when acceleration is 0.
    const double travel = std::max(distance(p, s.motions), 0.0) + pair.margin;
    shortest = std::min(
        shortest, 2.0 * travel / (speed + std::sqrt(speed * speed + 2.0 * acceleration * travel)));
  }
  return shortest;
}

}  // namespace gp::oracle
