#pragma once
// Exact contact between two placed shapes (FR:Determine-Collisions).

#include "engine/collision/manifold.hpp"
#include "engine/geometry/packed_geometry.hpp"
#include "engine/geometry/world_shape.hpp"

namespace gp {

/// Distance (m) under which two shapes' cores count as touching and the reference edge is kept
/// on A rather than B; half a millimetre, well below what a game can see.
inline constexpr double kContactTolerance = 5e-4;

/// The contact manifold between `a` and `b`, any kinds in either order, with the normal from b
/// towards a. Points whose surfaces are apart by at most `margin` (m, ≥ 0) are kept as
/// speculative points with negative depth; none are returned when the shapes are farther apart.
/// Two segments of radius 0 never touch (lines have no area). Swapping a and b negates the
/// normal and swaps the two halves of each feature id; the points stay the same unless both
/// shapes offer a face separating them equally (within kContactTolerance), where the reference
/// face is taken from a: call with the same order every frame for stable feature ids.
/// Does not allocate.
ContactManifold collide(const GeometryView& a, const GeometryView& b, double margin);
/// The same for two shapes as WorldShapes packs them: two polygons (two boxes: a box pile's every
/// pair) and two discs (a rain's) are collided without being viewed first.
ContactManifold collide(const PackedGeometry& a, const PackedGeometry& b, double margin);
/// Whether `a` and `b` are both discs, which collide() takes straight to their own collision.
inline bool two_discs(const PackedGeometry& a, const PackedGeometry& b) {
  return a.kind() == ShapeKind::kCircle && b.kind() == ShapeKind::kCircle;
}
/// How two discs' centres lie from each other: the part of their manifold whose square root and
/// division take longest, which a caller colliding many pairs can find for several pairs ahead so
/// that those overlap.
struct CentreGap {
  double distance;  ///< between the centres [m]
  Vec2 direction;   ///< unit, from b's centre towards a's (meaningless where distance is 0)
};
inline CentreGap centre_gap(const Circle& a, const Circle& b) {
  const Vec2 offset = a.center - b.center;
  const double distance = offset.norm();
  return {distance, offset / distance};
}
/// collide for two discs whose centre_gap is `gap`.
ContactManifold collide_circles(const Circle& a, const Circle& b, const CentreGap& gap,
                                double margin);
/// The same for placed shapes, whose boxes it does not need.
inline ContactManifold collide(const WorldShapeView& a, const WorldShapeView& b, double margin) {
  return collide(a.geometry, b.geometry, margin);
}

}  // namespace gp
