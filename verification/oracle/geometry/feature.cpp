#include "verification/oracle/geometry/feature.hpp"

#include "verification/oracle/geometry/placement.hpp"

namespace gp::oracle {

namespace {

/// The gap between the cores (radii not counted) [m].
double core_gap(const Feature& f, const PlacedHull& a, const PlacedHull& b) {
  switch (f.kind) {
    case Feature::Kind::VertexEdge:
      return (a.vertices[f.a] - b.vertices[f.b]).dot(edge_normal(b.vertices, f.b));
    case Feature::Kind::EdgeVertex:
      return (b.vertices[f.b] - a.vertices[f.a]).dot(edge_normal(a.vertices, f.a));
    case Feature::Kind::VertexVertex:
      break;
  }
  return (a.vertices[f.a] - b.vertices[f.b]).norm();
}

}  // namespace

double feature_gap(const Feature& feature, const PlacedHull& a, const PlacedHull& b) {
  return core_gap(feature, a, b) - a.radius - b.radius;
}

Vec2 feature_normal(const Feature& feature, const PlacedHull& a, const PlacedHull& b) {
  switch (feature.kind) {
    case Feature::Kind::VertexEdge:
      return edge_normal(b.vertices, feature.b);
    case Feature::Kind::EdgeVertex:
      return -edge_normal(a.vertices, feature.a);
    case Feature::Kind::VertexVertex:
      break;
  }
  const Vec2 offset = a.vertices[feature.a] - b.vertices[feature.b];
  const double length = offset.norm();
  return length > 0.0 ? Vec2(offset / length) : Vec2(0.0, 1.0);
}

Vec2 feature_point(const Feature& feature, const PlacedHull& a, const PlacedHull& b) {
  const Vec2 n = feature_normal(feature, a, b);
  const double gap = core_gap(feature, a, b);
  // A's surface point and B's lie on the line along n through the feature's vertex, `gap` apart
  // between the cores; each surface stands its radius off its core.
  if (feature.kind == Feature::Kind::EdgeVertex) {
    const Vec2& on_b = b.vertices[feature.b];
    return on_b + 0.5 * (gap - a.radius + b.radius) * n;
  }
  const Vec2& on_a = a.vertices[feature.a];
  return on_a - 0.5 * (gap + a.radius - b.radius) * n;
}

}  // namespace gp::oracle
