#pragma once
// Candidate pairs for the narrowphase: the shapes whose bounding boxes overlap
// (FR:Determine-Collisions), found by sweep and prune instead of testing all pairs.

#include <algorithm>
#include <cmath>
#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "engine/collision/shape_pair.hpp"
#include "engine/geometry/aabb.hpp"

namespace gp {

/// What the broadphase pairs: `size()` boxes, read by index as `bounds(i)` (m, world; a
/// non-finite one makes find_pairs report no pair) and `is_static(i)` (its body never moves: two
/// static boxes are never paired). Read several times per call, rather than copied into a list
/// the size of the scene that the broadphase would keep.
template <typename Boxes>
concept BroadphaseBoxes = requires(const Boxes& boxes, std::uint32_t i) {
  { boxes.size() } -> std::convertible_to<std::size_t>;
  { boxes.bounds(i) } -> std::convertible_to<Aabb>;
  { boxes.is_static(i) } -> std::convertible_to<bool>;
};

/// A box given whole, for callers that have their boxes at hand.
struct BroadphaseProxy {
  Aabb bounds;     ///< m, world
  bool is_static;  ///< its body never moves
};

/// A list of proxies read as BroadphaseBoxes.
struct ProxyBoxes {
  std::span<const BroadphaseProxy> proxies;

  std::size_t size() const { return proxies.size(); }
  const Aabb& bounds(std::uint32_t i) const { return proxies[i].bounds; }
  bool is_static(std::uint32_t i) const { return proxies[i].is_static; }
};

/// Sweep and prune in horizontal bands. Plain sweep and prune sorts the boxes along x and tests
/// each only against those whose x intervals overlap its own; in a scene spread in both
/// directions that is about √N boxes each, N√N in all. Cutting the plane into bands about two
/// boxes high and sweeping each band on its own keeps that to a few per box: O(N log N + K) for
/// the sort and the K pairs found. A box spanning several bands is swept in each, and a pair is
/// reported only from the band holding the bottom of its overlap, so exactly once.
///
/// Bodies move little from one step to the next, so the entries are kept sorted between calls
/// and only repaired: the bands stay put while they still suit the boxes, an entry stays in its
/// band while its box still spans it, and an insertion sort restores the order along x in
/// O(N + moves). The moves are bounded: past O(N log N) of them the entries are sorted afresh,
/// so that a scene shuffled between calls costs no more than a rebuild.
class SweepAndPrune {
 public:
  /// `margin` (m, ≥ 0): boxes up to this far apart are paired too, so that the narrowphase can
  /// make speculative contacts with the same margin.
  explicit SweepAndPrune(double margin = 0.0) : half_margin_(0.5 * margin) {}

  /// Replaces `pairs` with the pairs of `boxes` (at most 2³⁰ of them) that, each grown by
  /// margin / 2 on every side, overlap (touching counts), except static with static, and perhaps
  /// a few more whose boxes are apart by less than a float's rounding of their sides (at most
  /// 2⁻²¹ of their largest coordinate: Entry); each pair once, in no particular order. The caller
  /// keeps the pairs, so that it can filter and sort them where they are. Allocates nothing once
  /// its buffers, and `pairs`, have grown to the scene. Fastest when each box keeps its index from
  /// call to call. Instantiated in broadphase.cpp for ProxyBoxes and SweptBoxes.
  template <BroadphaseBoxes Boxes>
  void find_pairs(const Boxes& boxes, std::vector<ShapePair>& pairs);
  void find_pairs(std::span<const BroadphaseProxy> proxies, std::vector<ShapePair>& pairs) {
    find_pairs(ProxyBoxes{proxies}, pairs);
  }

  /// Drops the entries and the bands and frees their room, for a caller that will not call for a
  /// while: the next call places and sorts them from scratch.
  void release();

  /// How many pairs of band entries the last call compared, those found plus those rejected:
  /// the measure of its cost.
  std::size_t candidates_tested() const { return candidates_tested_; }

  /// How many entries the last call sorted from scratch, rather than repaired from the order of
  /// the call before: the measure of how well the incremental update works.
  std::size_t entries_resorted() const { return entries_resorted_; }

 private:
  /// A grown box, in one of the bands it spans. 24 bytes, its sides floats rounded outwards
  /// (outward): there are more entries than boxes, and they are most of the broadphase's memory.
  /// A float box still holds its box, so every overlapping pair is still found; the bands, and so
  /// which band reports a pair, are placed from the doubles.
  struct Entry {
    float left;
    float right;
    float bottom;
    float top;
    std::int32_t band;
    /// Four times the index of the box in the call, plus the flags below.
    std::uint32_t tag;
    static constexpr std::uint32_t kStatic = 1;
    /// The band holds the box's bottom. The bottom of an overlap is the higher of the two
    /// bottoms, so the band holds it when it holds either box's bottom.
    static constexpr std::uint32_t kBottom = 2;

    std::uint32_t box() const { return tag >> 2; }
    bool has(std::uint32_t flag) const { return (tag & flag) != 0; }

    bool operator<(const Entry& other) const {
      return band != other.band ? band < other.band : left < other.left;
    }
  };

  /// The bands [first, last] a box's entries are in; none when first > last. The bands that
  /// hold entries number at most about 2N (see bands_suit), so 32 bits count them.
  struct BandRange {
    std::int32_t first;
    std::int32_t last;
  };

  /// What one pass over the boxes finds for placing the bands.
  struct Survey {
    bool usable = false;   ///< the boxes, and the spread of their bottoms, are finite
    double lowest = 0.0;   ///< m: the lowest grown bottom
    double highest = 0.0;  ///< m: the highest grown bottom
    /// The grown boxes no taller than the band height of the last call, and those shorter than a
    /// quarter of it (see bands_suit).
    std::size_t up_to_band = 0;
    std::size_t below_quarter_band = 0;
  };
  template <typename Boxes>
  Survey survey(const Boxes& boxes) const;

  /// Twice the median box height (m), widened when needed so that there are at most about N
  /// bands across `bottoms_range` (m), the spread of the boxes' bottoms: a single huge box then
  /// cannot make more entries than there are boxes.
  template <typename Boxes>
  double ideal_band_height(const Boxes& boxes, double bottoms_range) const;
  /// The height of rank N / 2 (from 0) of the grown boxes (m).
  template <typename Boxes>
  double median_height(const Boxes& boxes) const;
  double grown_height(const Aabb& box) const {
    return box.max.y() - box.min.y() + 2.0 * half_margin_;
  }
  /// Keeps the bands of the last call when they still suit the `count` boxes `survey` describes;
  /// else places them anew and forgets the entries.
  template <typename Boxes>
  void place_bands(const Boxes& boxes, const Survey& survey);
  /// Whether the bands of the last call still suit those boxes: a height within a factor of two
  /// of ideal_band_height, found in O(N) without the median's copy and selection.
  bool bands_suit(std::size_t count, const Survey& survey) const;
  std::int64_t band_of(double y) const {
    // A top far above the bottoms (up to the largest double, over a height that may itself be
    // infinite) lies in a band past the last one that matters: clamped, NaN included, so that the
    // conversion stays defined.
    constexpr double kBeyondAnyBand = 0x1p62;
    const double band = (y - band_origin_) / band_height_;
    return static_cast<std::int64_t>(band < kBeyondAnyBand ? band : kBeyondAnyBand);
  }
  /// The bands a grown box has entries in, up to `last_band`, that of the highest grown bottom.
  BandRange bands_of(const Aabb& grown, std::int64_t last_band) const {
    // Between 0 (no bottom is below the origin) and last_band, which 32 bits hold.
    return {static_cast<std::int32_t>(band_of(grown.min.y())),
            static_cast<std::int32_t>(std::min(band_of(grown.max.y()), last_band))};
  }
  /// Brings the entries of the last call to `boxes`, whose highest grown bottom is `highest` (m):
  /// drops those whose box left their band, refreshes the others, adds those of the bands newly
  /// spanned, and sorts them again.
  template <typename Boxes>
  void update_entries(const Boxes& boxes, double highest);
  /// Makes every entry anew and sorts them, when none is kept from the last call.
  template <typename Boxes>
  void build_entries(const Boxes& boxes, std::int64_t last_band);
  /// Restores the order of the entries kept from the last call, then merges in those added.
  void sort_entries();
  void sweep(std::vector<ShapePair>& pairs);
  /// `x` rounded outwards to a float (`out` −1 for a lower side, +1 for an upper one), by at most
  /// 2⁻²² of |x| and the least float: moved out by at least a float's step (2⁻²⁴ to 2⁻²³ of |x|),
  /// then rounded to nearest, which moves back by at most half of one. No branch on which way the
  /// rounding went (float_below's), which goes either way at random at every side of every box at
  /// every step: it took rain4000's broadphase from 181 to 225–269 µs a step. Past the largest
  /// float, where a conversion is undefined, the largest float or infinity.
  static float outward(double x, double out) {
    constexpr double kLargest = std::numeric_limits<float>::max();
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    const double moved = x + out * (std::abs(x) * 0x1p-23 + 0x1p-149);
    if (moved > kLargest) return out > 0.0 ? kInfinity : std::numeric_limits<float>::max();
    if (moved < -kLargest) return out < 0.0 ? -kInfinity : std::numeric_limits<float>::lowest();
    return static_cast<float>(moved);
  }
  /// The entry in `band` of box `i`, grown to `grown`, whose bands are `bands`.
  static Entry entry(const Aabb& grown, std::int32_t band, std::uint32_t i, const BandRange& bands,
                     bool is_static) {
    return Entry{
        outward(grown.min.x(), -1.0),
        outward(grown.max.x(), 1.0),
        outward(grown.min.y(), -1.0),
        outward(grown.max.y(), 1.0),
        band,
        i << 2 | (is_static ? Entry::kStatic : 0) | (band == bands.first ? Entry::kBottom : 0)};
  }
  /// Drops the entries and the bands: the next call places and sorts them from scratch.
  void forget();

  // At least this many boxes or entries are shared out among threads, this many a task: a box
  // costs tens of nanoseconds, handing out a task about a microsecond.
  static constexpr std::size_t kParallelBoxes = 4096;
  static constexpr std::size_t kBoxesPerTask = 1024;

  double half_margin_;
  double band_origin_ = 0.0;  // m: at or below the lowest grown box bottom
  double band_height_ = 0.0;  // m; 0 while no bands are placed
  std::size_t candidates_tested_ = 0;
  std::size_t entries_resorted_ = 0;
  std::vector<BandRange> bands_;  // per box of the last call, then of this one
  std::vector<Entry> entries_;    // sorted by band, then left, between calls
  std::vector<Entry> added_;      // scratch: entries of bands newly spanned
  // Of a call shared out among threads: each thread's added entries, and per block of entries
  // swept, where its pairs start in the list (then one past the last) and its candidates.
  tbb::enumerable_thread_specific<std::vector<Entry>> thread_added_;
  std::vector<std::size_t> block_pairs_;
  std::vector<std::size_t> block_tested_;
};

}  // namespace gp
