#include "engine/geometry/world_bounds.hpp"

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

}  // namespace gp
