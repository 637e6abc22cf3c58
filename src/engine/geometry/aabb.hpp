#pragma once
// Axis-aligned bounding box: the cheap stand-in for a shape in the broadphase.

#include <algorithm>

#include "gamephysics/models/types.hpp"

namespace gp {

/// Box [min.x, max.x] × [min.y, max.y] in world coordinates (m). Closed: touching boxes overlap.
struct Aabb {
  Vec2 min;
  Vec2 max;

  bool overlaps(const Aabb& other) const {
    return min.x() <= other.max.x() && other.min.x() <= max.x() && min.y() <= other.max.y() &&
           other.min.y() <= max.y();
  }

  /// The widest gap between this box and `other` along an axis [m]: no point of one is nearer to
  /// a point of the other; not above 0 when they overlap.
  double gap_to(const Aabb& other) const {
    return std::max(std::max(min.x() - other.max.x(), other.min.x() - max.x()),
                    std::max(min.y() - other.max.y(), other.min.y() - max.y()));
  }

  /// The smallest box holding this one and `other`.
  Aabb united(const Aabb& other) const {
    return {min.cwiseMin(other.min), max.cwiseMax(other.max)};
  }

  /// The smallest box holding this one and point `p`.
  Aabb grown_to(const Vec2& p) const { return {min.cwiseMin(p), max.cwiseMax(p)}; }

  /// This box grown by `margin` (m) on every side.
  Aabb fattened(double margin) const {
    // Not a Vec2(margin, margin): built from two scalars, it went through the stack, and the
    // wide load of it stalled on the two narrow stores (a third of the broadphase's update).
    return {(min.array() - margin).matrix(), (max.array() + margin).matrix()};
  }
};

}  // namespace gp
