#pragma once
// The enlarged boxes whose pairs CandidatePairs keeps, stored as floats rounded outwards: half the
// room of doubles, and each still holds the box it was made from, which is all that is asked of
// it. Internal to collision/.

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include "engine/collision/float_rounding.hpp"
#include "engine/geometry/aabb.hpp"

namespace gp {

struct EnlargedBox {
  float min_x, min_y, max_x, max_y;  ///< m, world

  Aabb bounds() const { return {{min_x, min_y}, {max_x, max_y}}; }
};

/// The smallest box of floats holding `box` (m); none when a side is not finite or beyond the
/// range of a float.
inline std::optional<EnlargedBox> enlarged_box(const Aabb& box) {
  constexpr double kLargest = std::numeric_limits<float>::max();
  const double sides[] = {box.min.x(), box.min.y(), box.max.x(), box.max.y()};
  for (const double side : sides) {
    if (!(std::abs(side) <= kLargest)) return std::nullopt;
  }
  return EnlargedBox{float_below(box.min.x()), float_below(box.min.y()), float_above(box.max.x()),
                     float_above(box.max.y())};
}

/// BroadphaseBoxes of enlarged boxes, shape i static when `fixed[i]` is non-zero.
struct EnlargedBoxes {
  std::span<const EnlargedBox> boxes;
  std::span<const std::uint8_t> fixed;

  std::size_t size() const { return boxes.size(); }
  Aabb bounds(std::uint32_t i) const { return boxes[i].bounds(); }
  bool is_static(std::uint32_t i) const { return fixed[i] != 0; }
};

}  // namespace gp
