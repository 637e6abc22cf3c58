#pragma once
// Every shape of a space placed in the world at one instant, stored compactly: a disc or a segment
// is packed whole, its box made again when it is read, and the polygons' vertices, normals and
// boxes share one pool sized to their own vertex counts instead of a WorldShape's room for
// kMaxPolygonVertices each.

#include <cstddef>
#include <vector>

#include "engine/geometry/packed_geometry.hpp"
#include "engine/geometry/world_shape.hpp"
#include "engine/prefetch.hpp"

namespace gp {

class WorldShapes {
 public:
  WorldShapes() = default;
  // A copy's polygon views would still point into the original's pool.
  WorldShapes(const WorldShapes&) = delete;
  WorldShapes& operator=(const WorldShapes&) = delete;

  /// Forgets every placement and makes room for `count` shapes, `polygons` of them polygons with
  /// `polygon_vertices` vertices in all. Each shape must then be placed before it is read.
  void lay_out(std::size_t count, std::size_t polygons, std::size_t polygon_vertices);
  /// Forgets every placement, so that the shapes are laid out again.
  void clear() { shapes_.clear(); }

  /// Places shape `i`, `local` (body frame) moved into the world by `transform`. A polygon keeps
  /// the room it was first given, and so must keep its vertex count.
  void place(std::size_t i, const GeometryView& local, const Transform& transform);
  /// The same for a shape kept packed (see ShapeRecord), without viewing it first.
  void place(std::size_t i, const PackedGeometry& local, const Transform& transform);

  std::size_t size() const { return shapes_.size(); }
  /// Asks for the cache lines that placing shape `i` again writes (prefetch.hpp).
  void prefetch_for_placing(std::size_t i) const {
    const PackedGeometry& shape = shapes_[i];
    prefetch_for_writing(&shape, sizeof(PackedGeometry));
    if (shape.kind() != ShapeKind::kPolygon) return;
    const PolygonView polygon = shape.polygon();
    prefetch_for_writing(polygon.vertices.data(), (2 * polygon.vertices.size() + 2) * sizeof(Vec2));
  }
  /// The box of shape `i` as placed, without the view around it.
  Aabb bounds(std::size_t i) const {
    const PackedGeometry& shape = shapes_[i];
    switch (shape.kind()) {
      case ShapeKind::kCircle:
        return bounds_of(shape.circle());
      case ShapeKind::kSegment:
        return bounds_of(shape.segment());
      case ShapeKind::kPolygon:
        break;
    }
    const PolygonView polygon = shape.polygon();
    const Vec2* box = polygon.normals.data() + polygon.normals.size();
    return {box[0], box[1]};
  }
  /// The geometry of shape `i` as placed, without its box.
  GeometryView geometry(std::size_t i) const { return shapes_[i].view(); }
  /// The same, packed as it is kept: what the narrowphase reads.
  const PackedGeometry& packed(std::size_t i) const { return shapes_[i]; }
  /// Shape `i` as placed, viewed: made when asked for, so hold it by value or by a const
  /// reference bound to the call.
  WorldShapeView operator[](std::size_t i) const { return {shapes_[i].view(), bounds(i)}; }

 private:
  /// Places polygon `local` in the room of shape i in the pool, given it on its first placement.
  void place_in_pool(std::size_t i, const PolygonView& local, const Transform& transform);

  std::vector<PackedGeometry> shapes_;
  std::vector<Vec2> pool_;  // per polygon, its vertices, its normals, its box's min and max
};

}  // namespace gp
