#pragma once
// A shape placed in the world by its body's transform: what collision detection works on.

#include <span>

#include "engine/geometry/aabb.hpp"
#include "engine/geometry/transform.hpp"
#include "scene/shape.hpp"

namespace gp {

/// The geometry of a Shape in world coordinates (m; polygon normals turned with it) and its
/// tight bounding box (m). Made by to_world, which keeps the Shape's invariants.
struct WorldShape {
  ShapeGeometry geometry;
  Aabb bounds;

  ShapeKind kind() const { return kind_of(geometry); }
};

/// A WorldShape whose polygon, if it is one, is stored elsewhere: what the narrowphase reads.
struct WorldShapeView {
  GeometryView geometry;
  Aabb bounds;

  WorldShapeView() = default;
  /// `placed`: a GeometryView or one of its alternatives, which then goes in without a variant
  /// made on the way.
  template <typename Geometry>
  WorldShapeView(const Geometry& placed, const Aabb& box) : geometry(placed), bounds(box) {}
  /// Views `shape`, which must outlive the view (as a std::string does its std::string_view).
  WorldShapeView(const WorldShape& shape)  // NOLINT(google-explicit-constructor)
      : geometry(view_of(shape.geometry)), bounds(shape.bounds) {}

  ShapeKind kind() const { return kind_of(geometry); }
};

/// The tight bounding boxes of a disc and of a segment (m). The radius is subtracted and added as
/// a scalar, not as a Vec2 built from two (see Aabb::fattened).
inline Aabb bounds_of(const Circle& circle) {
  return {(circle.center.array() - circle.radius).matrix(),
          (circle.center.array() + circle.radius).matrix()};
}
inline Aabb bounds_of(const Segment& segment) {
  return {(segment.a.cwiseMin(segment.b).array() - segment.radius).matrix(),
          (segment.a.cwiseMax(segment.b).array() + segment.radius).matrix()};
}

/// A disc and a segment (body frame) moved into the world by their body's `transform`: what both
/// a WorldShape and a packed placement (WorldShapes) hold of them.
inline Circle moved(const Circle& circle, const Transform& transform) {
  return {transform.apply(circle.center), circle.radius};
}
inline Segment moved(const Segment& segment, const Transform& transform) {
  return {transform.apply(segment.a), transform.apply(segment.b), segment.radius};
}

/// The shape `local` (body frame) moved into the world by its body's `transform`.
WorldShape to_world(const GeometryView& local, const Transform& transform);

inline WorldShape to_world(const Shape& shape, const Transform& transform) {
  return to_world(view_of(shape.geometry()), transform);
}

/// Writes `polygon` moved into the world by `transform` to `vertices` and `normals` (as many as
/// the polygon's) and returns its bounding box.
Aabb place_polygon(const PolygonView& polygon, const Transform& transform, std::span<Vec2> vertices,
                   std::span<Vec2> normals);

/// The bounding box of `polygon` moved into the world by `transform`, without placing it: the
/// same box as place_polygon's, bit for bit.
Aabb placed_bounds(const PolygonView& polygon, const Transform& transform);

}  // namespace gp
