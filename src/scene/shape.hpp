#pragma once
// The collision shapes a body can carry (FR:Determine-Collisions), in the body frame, and the
// validating factories that are the only way to make one.

#include <array>
#include <span>
#include <variant>

#include "gamephysics/models/types.hpp"

namespace gp {

/// Most vertices a convex polygon may have. A fixed capacity keeps polygons in fixed-size arrays,
/// so that collision detection never allocates; rounder outlines are better made as circles or
/// capsules than as many-sided polygons.
inline constexpr int kMaxPolygonVertices = 8;

/// Disc of `radius` (m, > 0) centred at `center` (m).
struct Circle {
  Vec2 center;
  double radius;
};

/// Convex polygon with `count` (3 to kMaxPolygonVertices) vertices (m) in counter-clockwise
/// order, no three collinear; normals[i] is the outward unit normal of the edge from vertex i to
/// vertex i + 1 (mod count). Entries from `count` on are unused.
struct ConvexPolygon {
  std::array<Vec2, kMaxPolygonVertices> vertices;
  std::array<Vec2, kMaxPolygonVertices> normals;
  int count;
};

/// Segment from `a` to `b` (m, distinct) swept by a disc of `radius` (m, ≥ 0): a capsule, or a
/// bare line (no area) when the radius is 0.
struct Segment {
  Vec2 a;
  Vec2 b;
  double radius;
};

/// The alternatives of ShapeGeometry, in the same order.
enum class ShapeKind { kCircle, kPolygon, kSegment };

using ShapeGeometry = std::variant<Circle, ConvexPolygon, Segment>;

inline ShapeKind kind_of(const ShapeGeometry& geometry) {
  return static_cast<ShapeKind>(geometry.index());
}

/// A convex polygon's vertices and outward edge normals (m, as in ConvexPolygon), viewed where
/// they are stored.
struct PolygonView {
  std::span<const Vec2> vertices;
  std::span<const Vec2> normals;
};

/// A ShapeGeometry whose polygon is viewed instead of held: a quarter of its size, and what the
/// engine keeps per shape. The alternatives are in the same order.
using GeometryView = std::variant<Circle, PolygonView, Segment>;

inline ShapeKind kind_of(const GeometryView& geometry) {
  return static_cast<ShapeKind>(geometry.index());
}

/// Views `geometry`, which must outlive the view (as a std::string does its std::string_view).
GeometryView view_of(const ShapeGeometry& geometry);

/// A validated shape in its body's frame. Every factory throws std::invalid_argument, naming the
/// rule broken and the offending value, for non-finite numbers or a degenerate shape.
class Shape {
 public:
  /// Disc of `radius` (m, finite, > 0) centred at `center` (m).
  static Shape circle(double radius, const Vec2& center = Vec2::Zero());

  /// Convex polygon through `vertices` (m), in either winding: clockwise input is reordered to
  /// counter-clockwise. Consecutive repeats of a vertex are merged; what remains must be 3 to
  /// kMaxPolygonVertices vertices enclosing a non-zero area, strictly convex (no reflex angle,
  /// no three collinear vertices, not self-intersecting).
  static Shape polygon(std::span<const Vec2> vertices);

  /// Axis-aligned rectangle `width` × `height` (m, finite, > 0) centred at `center` (m).
  static Shape box(double width, double height, const Vec2& center = Vec2::Zero());

  /// Segment from `a` to `b` (m, finite, distinct) with rounding `radius` (m, finite, ≥ 0).
  static Shape segment(const Vec2& a, const Vec2& b, double radius = 0.0);

  /// The shape that `geometry`, a view of a Shape's geometry, shows: made again by its kind's
  /// factory, which gives back the same numbers.
  static Shape copy_of(const GeometryView& geometry);

  ShapeKind kind() const { return kind_of(geometry_); }
  const ShapeGeometry& geometry() const { return geometry_; }

 private:
  explicit Shape(const ShapeGeometry& geometry) : geometry_(geometry) {}

  ShapeGeometry geometry_;
};

}  // namespace gp
