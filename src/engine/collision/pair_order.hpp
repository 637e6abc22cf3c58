#pragma once
// Candidate pairs in one order whatever order the broadphase found them in, so that the solver's
// order, and so the result, does not depend on the broadphase's internals.

#include <cstdint>
#include <vector>

#include "engine/collision/broadphase.hpp"

namespace gp {

/// Sorts pairs of ids below a bound by (first, second) in O(K + bound) for K pairs: a radix sort
/// with one digit per id, where a comparison sort takes O(K log K).
class PairOrder {
 public:
  /// Sorts `pairs`, whose ids are all below `id_bound`, ascending. Allocates nothing once its
  /// buffers have grown to the scene.
  void sort(std::vector<ShapePair>& pairs, std::uint32_t id_bound);

 private:
  std::vector<std::uint32_t> starts_;  // per id: where its pairs start in the output
  std::vector<ShapePair> scratch_;
};

}  // namespace gp
