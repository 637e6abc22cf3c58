#include "engine/collision/signed_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "engine/collision/hull.hpp"
#include "engine/geometry/closest_points.hpp"

namespace gp {

namespace {

// Every shape is a core (a point, a segment or a polygon) inflated by a radius. For convex cores
// the inflated shapes' signed distance is the cores' minus both radii, so only cores are measured.

/// A segment's two edges are the same line; a polygon has as many edges as vertices.
int edge_count(const Hull& hull) {
  return hull.count() == 2 ? 1 : hull.count();
}

// Squared: the root of the least is the least of the roots (a correctly rounded root is monotone),
// so the nearest edge costs one root instead of one per edge.
double squared_distance_to_edges(const Vec2& point, const Hull& hull) {
  double squared = std::numeric_limits<double>::infinity();
  for (int i = 0; i < edge_count(hull); ++i) {
    const Vec2& start = hull.vertices[i];
    const Vec2& end = hull.vertices[hull.next(i)];
    squared =
        std::min(squared, (point - closest_point_on_segment(point, start, end)).squaredNorm());
  }
  return squared;
}

// The most the vertex lies outside the hull's edges' lines [m]: negative inside.
double separation_of(const Vec2& vertex, const Hull& hull) {
  double separation = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < hull.count(); ++i) {
    separation = std::max(separation, hull.normals[i].dot(vertex - hull.vertices[i]));
  }
  return separation;
}

double core_distance(const Vec2& point, const Hull& hull) {
  if (hull.count() >= 3) {
    const double separation = separation_of(point, hull);
    // Inside: the nearest face is the way out.
    if (separation <= 0.0) return separation;
  }
  return std::sqrt(squared_distance_to_edges(point, hull));
}

// The vertex of `other` least beyond the line of `reference`'s edge `edge`: where the edge's
// separation was measured.
const Vec2& support(const Hull& reference, int edge, const Hull& other) {
  const Vec2& normal = reference.normals[edge];
  const Vec2& start = reference.vertices[edge];
  std::size_t least = 0;
  double separation = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < other.vertices.size(); ++j) {
    const double d = normal.dot(other.vertices[j] - start);
    if (d < separation) {
      separation = d;
      least = j;
    }
  }
  return other.vertices[least];
}

// Room [m] for the round-off of a length measured near `at`: a billionth of the lengths involved,
// far above the few ulps a separation or a gap can be off. Room only costs a test its shortcut.
double round_off_room(const Vec2& at, double length) {
  return 1e-9 * (1.0 + at.cwiseAbs().maxCoeff() + std::abs(length));
}

// Whether `vertex` is surely further than `gap` [m] from `hull`: beyond one of its edges' lines
// by more, the hull lying behind each. separation_of's loop, ending at the first such line: the
// whole loop costs the tumbler 0.8% more instructions.
bool further_than(const Vec2& vertex, const Hull& hull, double gap) {
  const double limit = gap + round_off_room(vertex, gap);
  for (int i = 0; i < hull.count(); ++i) {
    if (hull.normals[i].dot(vertex - hull.vertices[i]) > limit) return true;
  }
  return false;
}

// The separation of `a` and `b` along any edge normal bounds their gap from below: where it is
// above `beyond` [m] by more than its round-off, the gap surely is too.
bool surely_beyond(double separation, double beyond, const Hull& a) {
  return separation - round_off_room(a.vertices[0], separation) > beyond;
}

double core_distance(const Hull& a, const Hull& b, double beyond) {
  // Overlapping convex cores: the shortest way out is along one of the edge normals.
  const EdgeSeparation best_a = max_separation(a, b);
  const EdgeSeparation best_b = max_separation(b, a);
  const double separation = std::max(best_a.separation, best_b.separation);
  if (separation < 0.0 || surely_beyond(separation, beyond, a)) return separation;
  if (a.count() == 2 && b.count() == 2) {
    // No edge normal separates collinear segments, whatever their gap: measure it. (Parallel
    // segments never overlap in the test above: one side of a line is always clear of the other.)
    const SegmentClosestPoints closest =
        closest_points_between_segments(a.vertices[0], a.vertices[1], b.vertices[0], b.vertices[1]);
    return std::sqrt(closest.distance_squared);
  }
  // Apart: a separating edge normal only bounds the gap from below; the gap itself is between a
  // vertex of one and an edge of the other. The vertex nearest the most separating edge's line
  // is measured first; a vertex further beyond one of the other's edges than the least gap found
  // cannot hold the gap, and its edges are not measured. The least of the gaps measured is then
  // the least of them all, to the bit.
  const bool on_a = best_a.separation >= best_b.separation;
  const Hull& reference = on_a ? a : b;
  const Vec2& first = support(reference, on_a ? best_a.edge : best_b.edge, on_a ? b : a);
  double squared = squared_distance_to_edges(first, reference);
  double gap = std::sqrt(squared);
  const auto measure = [&](const Hull& from, const Hull& to) {
    for (const Vec2& v : from.vertices) {
      if (&v == &first || further_than(v, to, gap)) continue;
      const double s = squared_distance_to_edges(v, to);
      if (s < squared) {
        squared = s;
        gap = std::sqrt(squared);
      }
    }
  };
  measure(a, b);
  measure(b, a);
  return gap;
}

}  // namespace

double signed_distance(const WorldShapeView& a, const WorldShapeView& b, double beyond) {
  const auto* circle_a = std::get_if<Circle>(&a.geometry);
  const auto* circle_b = std::get_if<Circle>(&b.geometry);
  if (circle_a != nullptr && circle_b != nullptr) {
    return (circle_a->center - circle_b->center).norm() - circle_a->radius - circle_b->radius;
  }
  if (circle_a != nullptr || circle_b != nullptr) {
    const Circle& circle = circle_a != nullptr ? *circle_a : *circle_b;
    const GeometryView& other = circle_a != nullptr ? b.geometry : a.geometry;
    return visit_as_hull(other, [&](const Hull& hull) {
      return core_distance(circle.center, hull) - circle.radius - hull.radius;
    });
  }
  return visit_as_hull(a.geometry, [&](const Hull& hull_a) {
    return visit_as_hull(b.geometry, [&](const Hull& hull_b) {
      // The radii taken off one after the other, not as their sum, which would round otherwise.
      const double radii = hull_a.radius + hull_b.radius;
      return core_distance(hull_a, hull_b, beyond + radii) - hull_a.radius - hull_b.radius;
    });
  });
}

}  // namespace gp
