#include "verification/suite/stability_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "gamephysics/models/dd/kinetic_energy.hpp"

namespace gp::verification {

namespace {

// A shape in the world as the separating axis test sees it: the convex hull of its vertices
// swept by a disc of `radius` (a circle: one vertex; a segment: two; a polygon: its own).
struct Hull {
  std::vector<Vec2> vertices;
  double radius = 0.0;
  Vec2 lo;  // its bounding box, to pass over pairs far apart
  Vec2 hi;
};

Hull world_hull(const Shape& shape, const BodyState& at) {
  const double c = std::cos(at.angle);
  const double s = std::sin(at.angle);
  const auto place = [&](const Vec2& v) -> Vec2 {
    return at.position + Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
  };
  Hull h;
  if (const auto* circle = std::get_if<Circle>(&shape.geometry())) {
    h.vertices = {place(circle->center)};
    h.radius = circle->radius;
  } else if (const auto* p = std::get_if<ConvexPolygon>(&shape.geometry())) {
    for (int i = 0; i < p->count; ++i) h.vertices.push_back(place(p->vertices[i]));
  } else {
    const auto& segment = std::get<Segment>(shape.geometry());
    h.vertices = {place(segment.a), place(segment.b)};
    h.radius = segment.radius;
  }
  h.lo = h.hi = h.vertices.front();
  for (const Vec2& v : h.vertices) {
    h.lo = h.lo.cwiseMin(v);
    h.hi = h.hi.cwiseMax(v);
  }
  h.lo.array() -= h.radius;
  h.hi.array() += h.radius;
  return h;
}

// The candidate axes of a pair: every edge normal of either hull, and every direction from a
// vertex of one to a vertex of the other (the rounded corners' axes). The penetration direction
// of two rounded convex hulls is among them, so the least overlap over them is the depth.
std::vector<Vec2> axes(const Hull& a, const Hull& b) {
  std::vector<Vec2> out;
  for (const Hull* h : {&a, &b}) {
    const std::size_t n = h->vertices.size();
    for (std::size_t i = 0; i + 1 < n + (n > 2 ? 1 : 0); ++i) {
      const Vec2 edge = h->vertices[(i + 1) % n] - h->vertices[i];
      out.emplace_back(edge.y(), -edge.x());
    }
  }
  for (const Vec2& va : a.vertices) {
    for (const Vec2& vb : b.vertices) out.push_back(vb - va);
  }
  std::erase_if(out, [](const Vec2& axis) { return axis.norm() == 0.0; });
  for (Vec2& axis : out) axis.normalize();
  return out;
}

// [lowest, highest] of the hull projected on the unit `axis`.
std::pair<double, double> project(const Hull& h, const Vec2& axis) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Vec2& v : h.vertices) {
    lo = std::min(lo, v.dot(axis));
    hi = std::max(hi, v.dot(axis));
  }
  return {lo - h.radius, hi + h.radius};
}

double penetration(const Hull& a, const Hull& b) {
  if ((a.hi.array() < b.lo.array()).any() || (b.hi.array() < a.lo.array()).any()) return 0.0;
  double depth = std::numeric_limits<double>::infinity();
  for (const Vec2& axis : axes(a, b)) {
    const auto [a_lo, a_hi] = project(a, axis);
    const auto [b_lo, b_hi] = project(b, axis);
    depth = std::min(depth, std::min(a_hi - b_lo, b_hi - a_lo));
    if (depth <= 0.0) return 0.0;
  }
  return depth;
}

bool dynamic(const peers::PeerBody& body) {
  return body.type == BodyType::Dynamic;
}

}  // namespace

double largest_drift(const std::vector<peers::PeerBody>& bodies,
                     const std::vector<BodyState>& start, const std::vector<BodyState>& now) {
  double drift = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (dynamic(bodies[i])) drift = std::max(drift, (now[i].position - start[i].position).norm());
  }
  return drift;
}

double largest_overlap(const std::vector<peers::PeerBody>& bodies,
                       const std::vector<BodyState>& states) {
  struct Placed {
    Hull hull;
    std::size_t body;
  };
  std::vector<Placed> placed;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    for (const peers::PeerShape& s : bodies[i].shapes) {
      placed.push_back({world_hull(s.shape, states[i]), i});
    }
  }
  // Swept along x: a shape is tested against those whose boxes start before its own ends, so that
  // a pile of a thousand discs costs a sort rather than half a million pairs.
  std::sort(placed.begin(), placed.end(),
            [](const Placed& a, const Placed& b) { return a.hull.lo.x() < b.hull.lo.x(); });
  double overlap = 0.0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    for (std::size_t j = i + 1; j < placed.size() && placed[j].hull.lo.x() <= placed[i].hull.hi.x();
         ++j) {
      const std::size_t a = placed[i].body;
      const std::size_t b = placed[j].body;
      if (a == b || (!dynamic(bodies[a]) && !dynamic(bodies[b]))) continue;
      overlap = std::max(overlap, penetration(placed[i].hull, placed[j].hull));
    }
  }
  return overlap;
}

double largest_speed(const std::vector<peers::PeerBody>& bodies,
                     const std::vector<BodyState>& states) {
  double speed = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (dynamic(bodies[i])) speed = std::max(speed, states[i].velocity.norm());
  }
  return speed;
}

double kinetic_energy(const std::vector<peers::PeerBody>& bodies,
                      const std::vector<BodyState>& states) {
  double energy = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!dynamic(bodies[i])) continue;
    // A body that cannot rotate has an infinite moment and no rotational energy.
    const double moment = std::isfinite(bodies[i].moment) ? bodies[i].moment : 0.0;
    energy +=
        dd::kinetic_energy(bodies[i].mass, states[i].velocity, moment, states[i].angular_velocity);
  }
  return energy;
}

}  // namespace gp::verification
