#pragma once
// The bounding box of every shape of a space placed in the world at one instant, and nothing
// else: the broadphase needs no more of the shapes at the end of a step, and the time-of-impact
// search, their one other reader, places a pair there itself when it gets that far.

#include <cstddef>
#include <vector>

#include "engine/geometry/aabb.hpp"
#include "engine/geometry/packed_geometry.hpp"
#include "engine/geometry/transform.hpp"

namespace gp {

/// The tight bounding box (m) of shape `local` (body frame) moved into the world by
/// `transform`: bit for bit the box of the shape placed whole (to_world, WorldShapes).
Aabb placed_bounds(const PackedGeometry& local, const Transform& transform);

class WorldBounds {
 public:
  /// Forgets every placement and makes room for `count` shapes, each to be placed before it is
  /// read.
  void lay_out(std::size_t count) { boxes_.assign(count, {Vec2::Zero(), Vec2::Zero()}); }
  /// Forgets every placement, so that the shapes are laid out again.
  void clear() { boxes_.clear(); }

  /// Places shape `i`, `local` (body frame) moved into the world by `transform`.
  void place(std::size_t i, const PackedGeometry& local, const Transform& transform) {
    boxes_[i] = placed_bounds(local, transform);
  }

  std::size_t size() const { return boxes_.size(); }
  /// The box of shape `i` as placed [m].
  const Aabb& bounds(std::size_t i) const { return boxes_[i]; }

 private:
  std::vector<Aabb> boxes_;
};

}  // namespace gp
