#pragma once
// Every shape of a space placed in the world at one instant, stored compactly: a disc or a segment
// is held in its view, and the polygons' vertices and normals share one pool sized to their own
// vertex counts instead of a WorldShape's room for kMaxPolygonVertices each.

#include <cstddef>
#include <vector>

#include "engine/geometry/world_shape.hpp"

namespace gp {

class WorldShapes {
 public:
  WorldShapes() = default;
  // A copy's polygon views would still point into the original's pool.
  WorldShapes(const WorldShapes&) = delete;
  WorldShapes& operator=(const WorldShapes&) = delete;

  /// Forgets every placement and makes room for `count` shapes whose polygons have
  /// `polygon_vertices` vertices in all. Each shape must then be placed before it is read.
  void lay_out(std::size_t count, std::size_t polygon_vertices);
  /// Forgets every placement, so that the shapes are laid out again.
  void clear() { shapes_.clear(); }

  /// Places shape `i`, `local` (body frame) moved into the world by `transform`. A polygon keeps
  /// the room it was first given, and so must keep its vertex count.
  void place(std::size_t i, const GeometryView& local, const Transform& transform);

  std::size_t size() const { return shapes_.size(); }
  const WorldShapeView& operator[](std::size_t i) const { return shapes_[i]; }

 private:
  std::vector<WorldShapeView> shapes_;
  std::vector<Vec2> pool_;  // per polygon, its vertices then its normals
};

}  // namespace gp
