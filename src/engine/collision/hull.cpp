#include "engine/collision/hull.hpp"

#include <algorithm>
#include <limits>

namespace gp {

Hull hull_of(const PolygonView& polygon) {
  return {polygon.vertices, polygon.normals, 0.0};
}

SegmentOutline::SegmentOutline(const Segment& segment)
    : vertices_{segment.a, segment.b}, radius_(segment.radius) {
  const Vec2 edge = segment.b - segment.a;
  const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
  normals_ = {normal, -normal};
}

EdgeSeparation max_separation(const Hull& reference, const Hull& other) {
  EdgeSeparation best{0, -std::numeric_limits<double>::infinity()};
  for (int i = 0; i < reference.count(); ++i) {
    const Vec2& normal = reference.normals[i];
    const Vec2& origin = reference.vertices[i];
    double separation = std::numeric_limits<double>::infinity();
    for (const Vec2& v : other.vertices) separation = std::min(separation, normal.dot(v - origin));
    if (separation > best.separation) best = {i, separation};
  }
  return best;
}

int incident_edge(const Hull& hull, const Vec2& normal) {
  int best = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < hull.count(); ++i) {
    const double alignment = normal.dot(hull.normals[i]);
    if (alignment < lowest) {
      lowest = alignment;
      best = i;
    }
  }
  return best;
}

}  // namespace gp
