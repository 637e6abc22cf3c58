#pragma once
// A box holding every shape of a space placed in the world at one instant, and nothing else: the
// broadphase and the waking of sleeping islands need no more of the shapes at the end of a step,
// and the time-of-impact search places a pair there itself when it gets that far. A box moved
// from the shape's placement at the start of the step needs no sine, where the tight box of a
// turned shape needs one.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "engine/geometry/aabb.hpp"
#include "engine/geometry/packed_geometry.hpp"
#include "engine/geometry/transform.hpp"
#include "engine/prefetch.hpp"

namespace gp {

/// The tight bounding box (m) of shape `local` (body frame) moved into the world by
/// `transform`: bit for bit the box of the shape placed whole (to_world, WorldShapes).
Aabb placed_bounds(const PackedGeometry& local, const Transform& transform);

/// A box [m] that holds a shape whose box is `start` once its body has moved by `shift` [m] and
/// turned by `turn` [rad], the shape's core_reach being at most `reach` [m]: `start` moved by
/// `shift` and grown by |turn| · reach (at most 2 · reach), and by a little more for the
/// round-off of either placement. Inline: it is asked for every shape at every step.
inline Aabb moved_bounds(const Aabb& start, const Vec2& shift, double turn, double reach) {
  // A point turned about the centre of mass by Δθ moves by 2 |sin(Δθ / 2)| r: at most |Δθ| r, and
  // 2r whatever the turn. Each coordinate of either placement is rounded a few times, each by at
  // most an epsilon of the largest magnitude in it.
  constexpr double kRoundOff = 16.0 * std::numeric_limits<double>::epsilon();
  const double scale = std::max(start.min.cwiseAbs().maxCoeff(), start.max.cwiseAbs().maxCoeff()) +
                       shift.cwiseAbs().maxCoeff() + reach;
  const double growth = std::min(std::abs(turn), 2.0) * reach + kRoundOff * scale;
  return Aabb{start.min + shift, start.max + shift}.fattened(growth);
}

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

  /// Places shape `i` by a box that holds it (moved_bounds).
  void place(std::size_t i, const Aabb& box) { boxes_[i] = box; }

  std::size_t size() const { return boxes_.size(); }
  /// Asks for the cache line that placing shape `i` writes (prefetch.hpp).
  void prefetch_for_placing(std::size_t i) const { prefetch_for_writing(&boxes_[i], sizeof(Aabb)); }
  /// The box of shape `i` as placed [m].
  const Aabb& bounds(std::size_t i) const { return boxes_[i]; }

 private:
  std::vector<Aabb> boxes_;
};

}  // namespace gp
