#pragma once
// A shape placed in the world by its body's transform: what collision detection works on.

#include "engine/geometry/aabb.hpp"
#include "engine/geometry/shape.hpp"
#include "engine/geometry/transform.hpp"

namespace gp {

/// The geometry of a Shape in world coordinates (m; polygon normals turned with it) and its
/// tight bounding box (m). Made by to_world, which keeps the Shape's invariants.
struct WorldShape {
  ShapeGeometry geometry;
  Aabb bounds;

  ShapeKind kind() const { return kind_of(geometry); }
};

/// `shape` moved from its body's frame into the world by the body's `transform`.
WorldShape to_world(const Shape& shape, const Transform& transform);

}  // namespace gp
