#pragma once
// A candidate pair of shapes, by their indices in the space: what the broadphase finds and what
// contacts, impacts and warm starts are keyed by.

#include <compare>
#include <cstdint>

namespace gp {

/// The indices of two shapes whose boxes overlap, first < second.
struct ShapePair {
  std::uint32_t first;
  std::uint32_t second;

  auto operator<=>(const ShapePair&) const = default;
};

}  // namespace gp
