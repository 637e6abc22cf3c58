#pragma once
// Candidate pairs in one order whatever order the broadphase found them in, so that the solver's
// order, and so the result, does not depend on the broadphase's internals.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/collision/broadphase.hpp"

namespace gp {

/// Sorts pairs of ids below a bound by (first, second): a counting sort by first id, O(K + bound)
/// for K pairs where a comparison sort takes O(K log K), done in place (American flag sort) so as
/// to keep no second list as large as the pairs; then each first id's pairs, few but for a ground
/// or a wall, sorted by second.
class PairOrder {
 public:
  /// Sorts `pairs`, whose ids are all below `id_bound` and which are all different, ascending.
  /// Allocates nothing once its buffer has grown to the scene.
  void sort(std::vector<ProxyPair>& pairs, std::uint32_t id_bound);

 private:
  /// Where the pairs of one first id go: [next, end) is what is still to be filled.
  struct Bucket {
    std::uint32_t next;
    std::uint32_t end;
  };
  /// Sorts the pairs of one first id by second id.
  static void sort_by_second(std::span<ProxyPair> pairs);

  std::vector<Bucket> buckets_;  // per first id
};

}  // namespace gp
