#pragma once
// The candidate pairs of a step (FR:Determine-Collisions): the broadphase's pairs, less those of
// one body, sorted. A pile at rest makes the same pairs step after step, and finding them afresh
// (survey, band repair, sweep, sort) costs a few per cent of its step; such a scene's pairs come
// instead from pairs kept for boxes enlarged by a slack, filtered down to the boxes of the step.
// A box that leaves its enlarged copy is enlarged again where it is and its kept pairs found anew
// against every other enlarged box, as long as few do at once. The pairs are the same either way.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/collision/broadphase.hpp"
#include "engine/collision/enlarged_boxes.hpp"
#include "engine/collision/pair_order.hpp"
#include "engine/collision/swept_boxes.hpp"
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
  /// Forgets the pairs, kept or found, and frees the room they and the broadphase hold, for a
  /// caller that will not call for a while; the next call finds the pairs as the first did.
  void release();

  /// A box is enlarged by this fraction of its width plus its height, on every side (0.1 m for
  /// a unit box, Box2D's margin), when its dynamic body's pairs are kept.
  static constexpr double kSlack = 0.05;
  /// The most boxes outside their enlarged copies whose kept pairs are found anew one box at a
  /// time, each by a pass over every enlarged box; past it the kept list counts as outgrown.
  static constexpr std::size_t kRefreshedBoxes = 16;
  /// A box is on the move when its box over the step does not fit within its box at the start
  /// enlarged by this fraction of its slack: at that pace it leaves an enlarged copy within a
  /// few calls.
  static constexpr double kCalmTravel = 0.25;
  /// Calls running with at most kRefreshedBoxes boxes on the move before pairs are kept, and the
  /// fewest calls a kept list must serve: one outgrown sooner is dropped, and pairs found afresh
  /// until twice as many calls as the last time have been calm, up to kLongestWait.
  static constexpr int kCalmCalls = 2;
  static constexpr int kFewestServed = 8;
  static constexpr int kLongestWait = 256;

 private:
  /// Per shape in flags_: its body is static, and (for the call under way) its box has left its
  /// enlarged copy.
  static constexpr std::uint8_t kFixed = 1;
  static constexpr std::uint8_t kOutside = 2;

  std::size_t boxes_on_the_move(const SweptBoxes& boxes, const WorldShapes& start);
  template <typename Boxes>
  std::size_t boxes_outside_kept(const Boxes& boxes, bool same_bodies);
  template <typename Boxes>
  bool refresh_kept(const Boxes& boxes);
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
  // Pairs are kept once calm_needed_ calls running have been calm (see kCalmCalls).
  int calm_calls_ = 0;
  int calm_needed_ = kCalmCalls;
  bool keeping_ = false;
  int served_ = 0;  // calls the kept pairs have served since they were found
  bool used_kept_ = false;
  // While pairs are kept: per shape, its enlarged box and its flags (kFixed, kOutside); its box
  // of this call grown by margin / 2; and the pairs of the enlarged boxes, sorted. While they are
  // refreshed: the boxes outside, and their new pairs.
  std::vector<EnlargedBox> enlarged_;
  std::vector<std::uint8_t> flags_;
  std::vector<Aabb> grown_;
  std::vector<ShapePair> kept_;
  std::vector<std::uint32_t> outside_;
  std::vector<ShapePair> refreshed_;
  std::vector<std::size_t> block_counts_;  // per block of kept pairs filtered: the pairs left
};

}  // namespace gp
