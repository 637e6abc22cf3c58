#pragma once
// The candidate pairs of a step (FR:Determine-Collisions): the broadphase's pairs, less those of
// one body, sorted. A pile at rest makes the same pairs step after step, and finding them afresh
// (survey, band repair, sweep, sort) costs a few per cent of its step; such a scene's pairs come
// instead from pairs kept for boxes enlarged by a slack, filtered down to the boxes of the step,
// for as long as every box stays within its enlarged copy. The pairs are the same either way.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/collision/broadphase.hpp"
#include "engine/collision/enlarged_boxes.hpp"
#include "engine/collision/pair_order.hpp"
#include "engine/geometry/world_bounds.hpp"
#include "engine/geometry/world_shapes.hpp"

namespace gp {

class CandidatePairs {
 public:
  /// `margin` [m]: shapes this far apart are paired too.
  explicit CandidatePairs(double margin) : half_margin_(0.5 * margin), broadphase_(margin) {}

  /// The pairs of shapes of different bodies, at least one of them dynamic, whose boxes overlap
  /// when each is grown by margin / 2 after being made to cover both its `start` and its `end`
  /// placement; sorted by (first, second).
  const std::vector<ShapePair>& find(const BodyShapes& shapes, const std::vector<char>& dynamic,
                                     const WorldShapes& start, const WorldBounds& end);
  /// The pairs of the last find, which the caller may filter in place.
  std::vector<ShapePair>& pairs() { return pairs_; }

  /// Whether the last find filtered kept pairs rather than asking the broadphase.
  bool kept_pairs_used() const { return used_kept_; }

  /// A box is enlarged by this fraction of its width plus its height, on every side (0.1 m for
  /// a unit box, Box2D's margin), when its dynamic body's pairs are kept.
  static constexpr double kSlack = 0.05;
  /// Calls whose pairs must be the same before pairs are kept, and the fewest calls a kept list
  /// must serve: one outgrown sooner is dropped, and pairs found afresh until they have been the
  /// same for twice as many calls as the last time, up to kLongestSettling.
  static constexpr int kSettledCalls = 2;
  static constexpr int kFewestServed = 8;
  static constexpr int kLongestSettling = 256;

 private:
  template <typename Boxes>
  bool boxes_within_kept(const Boxes& boxes, bool same_bodies);
  template <typename Boxes>
  void keep_pairs(const Boxes& boxes);
  void filter_kept();
  void sort_and_drop_same_body(std::vector<ShapePair>& pairs);
  void forget_kept();

  double half_margin_;
  SweepAndPrune broadphase_;
  PairOrder pair_order_;
  std::vector<BodyId> body_of_;  // per shape
  std::vector<ShapePair> pairs_;
  // Pairs are kept once the pairs' fingerprint has been the same settle_needed_ calls running.
  std::uint64_t fingerprint_ = 0;
  int settled_calls_ = 0;
  int settle_needed_ = kSettledCalls;
  bool keeping_ = false;
  int served_ = 0;  // calls the kept pairs have served since they were found
  bool used_kept_ = false;
  // While pairs are kept: per shape, its enlarged box and whether it is static; its box of this
  // call grown by margin / 2; and the pairs of the enlarged boxes, sorted.
  std::vector<EnlargedBox> enlarged_;
  std::vector<std::uint8_t> fixed_;
  std::vector<Aabb> grown_;
  std::vector<ShapePair> kept_;
  std::vector<std::size_t> block_counts_;  // per block of kept pairs filtered: the pairs left
};

}  // namespace gp
