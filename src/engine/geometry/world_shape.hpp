#pragma once
// A shape placed in the world by its body's transform: what collision detection works on.

#include <span>
#include <variant>

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

/// A placed polygon's vertices and outward edge normals (m, world), where they are stored.
struct PolygonView {
  std::span<const Vec2> vertices;
  std::span<const Vec2> normals;
};

/// The alternatives of ShapeGeometry, a polygon viewed instead of held.
using WorldGeometryView = std::variant<Circle, PolygonView, Segment>;

/// A WorldShape whose polygon, if it is one, is stored elsewhere: what the narrowphase reads.
/// Holding no polygon storage, it is a quarter of a WorldShape's size.
struct WorldShapeView {
  WorldGeometryView geometry;
  Aabb bounds;

  WorldShapeView() = default;
  WorldShapeView(const WorldGeometryView& placed, const Aabb& box)
      : geometry(placed), bounds(box) {}
  /// Views `shape`, which must outlive the view (as a std::string does its std::string_view).
  WorldShapeView(const WorldShape& shape);  // NOLINT(google-explicit-constructor)

  ShapeKind kind() const { return static_cast<ShapeKind>(geometry.index()); }
};

/// `shape` moved from its body's frame into the world by the body's `transform`.
WorldShape to_world(const Shape& shape, const Transform& transform);

/// Writes `polygon` moved into the world by `transform` to `vertices` and `normals` (polygon.count
/// each) and returns its bounding box.
Aabb place_polygon(const ConvexPolygon& polygon, const Transform& transform,
                   std::span<Vec2> vertices, std::span<Vec2> normals);

}  // namespace gp
