#include "engine/geometry/world_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "engine/geometry/world_shape.hpp"

namespace gp {

Aabb placed_bounds(const PackedGeometry& local, const Transform& transform) {
  switch (local.kind()) {
    case ShapeKind::kCircle:
      return bounds_of(moved(local.circle(), transform));
    case ShapeKind::kSegment:
      return bounds_of(moved(local.segment(), transform));
    case ShapeKind::kPolygon:
      break;
  }
  return placed_bounds(local.polygon(), transform);
}

double turning_reach(const PackedGeometry& local) {
  switch (local.kind()) {
    case ShapeKind::kCircle:
      return local.circle().center.norm();
    case ShapeKind::kSegment:
      return std::max(local.segment().a.norm(), local.segment().b.norm());
    case ShapeKind::kPolygon:
      break;
  }
  double farthest = 0.0;
  for (const Vec2& v : local.polygon().vertices) farthest = std::max(farthest, v.squaredNorm());
  return std::sqrt(farthest);
}

}  // namespace gp
