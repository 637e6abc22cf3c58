#pragma once
// The boxes the broadphase pairs over a step: each shape's box at the start of the step united
// with its box at the end, read from the two placements when asked for rather than kept in a
// list of their own, which would take 32 bytes per shape more.

#include <cstdint>
#include <span>

#include "engine/geometry/aabb.hpp"
#include "engine/geometry/world_bounds.hpp"
#include "engine/geometry/world_shapes.hpp"

namespace gp {

/// BroadphaseBoxes of the shapes placed in `start` and `end`: shape i belongs to body
/// `body_of[i]`, which moves in collisions when `dynamic[body]` is non-zero.
class SweptBoxes {
 public:
  SweptBoxes(const WorldShapes& start, const WorldBounds& end,
             std::span<const std::uint32_t> body_of, std::span<const char> dynamic)
      : start_(start), end_(end), body_of_(body_of), dynamic_(dynamic) {}

  std::size_t size() const { return body_of_.size(); }
  Aabb bounds(std::uint32_t i) const { return start_.bounds(i).united(end_.bounds(i)); }
  /// Whether collisions cannot move shape i's body: the broadphase pairs no two such shapes.
  bool is_static(std::uint32_t i) const { return dynamic_[body_of_[i]] == 0; }

 private:
  const WorldShapes& start_;
  const WorldBounds& end_;
  std::span<const std::uint32_t> body_of_;
  std::span<const char> dynamic_;
};

}  // namespace gp
