#include "engine/collision/candidate_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>

#include "engine/capacity.hpp"
#include "engine/threads.hpp"

namespace gp {

namespace {

// At least this many shapes, or kept pairs, are shared out among threads, this many a task: a
// box or a pair costs nanoseconds, handing out a task about a microsecond.
constexpr std::size_t kParallelCount = 4096;
constexpr std::size_t kPerTask = 1024;

bool holds(const Aabb& outer, const Aabb& inner) {
  return inner.min.x() >= outer.min.x() && inner.min.y() >= outer.min.y() &&
         inner.max.x() <= outer.max.x() && inner.max.y() <= outer.max.y();
}

// The enlarged copy of a shape's box. A static body's box never moves; a kinematic one's, which
// moves, leaves its copy at its first move.
std::optional<EnlargedBox> enlarged_copy(const Aabb& box, bool fixed) {
  const double slack = fixed ? 0.0 : CandidatePairs::kSlack * (box.max - box.min).sum();
  return enlarged_box(box.fattened(slack));
}

}  // namespace

const std::vector<ShapePair>& CandidatePairs::find(const BodyShapes& shapes,
                                                   const std::vector<char>& dynamic,
                                                   const WorldShapes& start,
                                                   const WorldBounds& end) {
  // The shapes' bodies side by side: the broadphase and the pairs below look them up at random,
  // and a whole shape record per look-up costs a cache miss each in a large scene.
  bool same_bodies = body_of_.size() == shapes.size();
  body_of_.resize(shapes.size());
  for (std::uint32_t i = 0; i < shapes.size(); ++i) {
    same_bodies = same_bodies && body_of_[i] == shapes[i].body;
    body_of_[i] = shapes[i].body;
  }
  const SweptBoxes boxes(start, end, body_of_, dynamic);
  used_kept_ = false;
  if (keeping_) {
    const std::size_t outside = boxes_outside_kept(boxes, same_bodies);
    if (outside <= kRefreshedBoxes && (outside == 0 || refresh_kept(boxes))) {
      filter_kept();
      used_kept_ = true;
      // Kept pairs that last are a pile at rest: the broadphase's room is freed meanwhile, so
      // that the pile holds little more than it did. Pairs outgrown sooner leave it in place.
      if (++served_ == kFewestServed) broadphase_.release();
      return pairs_;
    }
    if (served_ >= kFewestServed) {
      calm_needed_ = kCalmCalls;
      keep_pairs(boxes);
      if (keeping_) {
        filter_kept();
        return pairs_;
      }
    } else {
      // Outgrown too soon: the bodies are on the move. Wait longer each time before keeping again.
      calm_needed_ = std::min(2 * calm_needed_, kLongestWait);
      forget_kept();
    }
  }
  broadphase_.find_pairs(boxes, pairs_);
  sort_and_drop_same_body(pairs_);
  calm_calls_ = boxes_on_the_move(boxes, start) <= kRefreshedBoxes ? calm_calls_ + 1 : 0;
  if (calm_calls_ >= calm_needed_) keep_pairs(boxes);
  return pairs_;
}

std::size_t CandidatePairs::boxes_on_the_move(const SweptBoxes& boxes, const WorldShapes& start) {
  const std::size_t n = boxes.size();
  return reduce_blocks(
      n, kPerTask, n < kParallelCount, std::size_t{0},
      [&](std::size_t first, std::size_t last, std::size_t moving) {
        for (auto i = static_cast<std::uint32_t>(first); i < last; ++i) {
          const Aabb at_start = start.bounds(i);
          const double slack = kSlack * (at_start.max - at_start.min).sum();
          moving += holds(at_start.fattened(kCalmTravel * slack), boxes.bounds(i)) ? 0 : 1;
        }
        return moving;
      },
      std::plus<>());
}

template <typename Boxes>
std::size_t CandidatePairs::boxes_outside_kept(const Boxes& boxes, bool same_bodies) {
  const std::size_t n = boxes.size();
  reserve_for(grown_, n);
  grown_.resize(n);
  const bool comparable = same_bodies && enlarged_.size() == n;
  constexpr std::size_t kIncomparable = std::numeric_limits<std::size_t>::max();
  // Every box grown, for filter_kept or the broadphase, even once the kept pairs cannot serve.
  return reduce_blocks(
      n, kPerTask, n < kParallelCount, std::size_t{0},
      [&](std::size_t first, std::size_t last, std::size_t outside) {
        for (auto i = static_cast<std::uint32_t>(first); i < last; ++i) {
          const Aabb box = boxes.bounds(i);
          grown_[i] = box.fattened(half_margin_);
          if (!comparable || ((flags_[i] & kFixed) != 0) != boxes.is_static(i)) {
            outside = kIncomparable;
          } else if (outside != kIncomparable) {
            const bool out = !holds(enlarged_[i].bounds(), box);
            flags_[i] = static_cast<std::uint8_t>((flags_[i] & kFixed) | (out ? kOutside : 0));
            outside += out ? 1 : 0;
          }
        }
        return outside;
      },
      [](std::size_t a, std::size_t b) {
        return a == kIncomparable || b == kIncomparable ? kIncomparable : a + b;
      });
}

template <typename Boxes>
bool CandidatePairs::refresh_kept(const Boxes& boxes) {
  outside_.clear();
  for (std::uint32_t i = 0; i < flags_.size(); ++i) {
    if ((flags_[i] & kOutside) == 0) continue;
    const std::optional<EnlargedBox> enlarged =
        enlarged_copy(boxes.bounds(i), (flags_[i] & kFixed) != 0);
    if (!enlarged) return false;
    enlarged_[i] = *enlarged;
    append(outside_, i);
  }
  // The pairs the broadphase would find among the enlarged boxes (see keep_pairs) that hold a
  // box outside: each such box against every other, a pair of two of them from the higher one.
  const auto grown = [this](std::uint32_t i) {
    return enlarged_[i].bounds().fattened(half_margin_);
  };
  refreshed_.clear();
  for (const std::uint32_t i : outside_) {
    const Aabb box = grown(i);
    for (std::uint32_t j = 0; j < flags_.size(); ++j) {
      if (!grown(j).overlaps(box)) continue;
      if (j == i || ((flags_[j] & kOutside) != 0 && j > i)) continue;
      if ((flags_[i] & flags_[j] & kFixed) != 0 || body_of_[i] == body_of_[j]) continue;
      refreshed_.push_back({std::min(i, j), std::max(i, j)});
    }
  }
  std::erase_if(kept_, [this](const ShapePair& p) {
    return ((flags_[p.first] | flags_[p.second]) & kOutside) != 0;
  });
  std::sort(refreshed_.begin(), refreshed_.end());
  const auto kept = static_cast<std::ptrdiff_t>(kept_.size());
  reserve_for(kept_, kept_.size() + refreshed_.size());
  kept_.insert(kept_.end(), refreshed_.begin(), refreshed_.end());
  std::inplace_merge(kept_.begin(), kept_.begin() + kept, kept_.end());
  for (const std::uint32_t i : outside_) flags_[i] &= kFixed;
  return true;
}

template <typename Boxes>
void CandidatePairs::keep_pairs(const Boxes& boxes) {
  const std::size_t n = boxes.size();
  reserve_for(enlarged_, n);
  enlarged_.resize(n);
  reserve_for(flags_, n);
  flags_.resize(n);
  const bool representable = reduce_blocks(
      n, kPerTask, n < kParallelCount, true,
      [&](std::size_t first, std::size_t last, bool all) {
        for (auto i = static_cast<std::uint32_t>(first); i < last; ++i) {
          const bool fixed = boxes.is_static(i);
          const std::optional<EnlargedBox> enlarged = enlarged_copy(boxes.bounds(i), fixed);
          all = all && enlarged.has_value();
          if (enlarged) enlarged_[i] = *enlarged;
          flags_[i] = fixed ? kFixed : 0;
        }
        return all;
      },
      [](bool a, bool b) { return a && b; });
  // A box not finite, or beyond the range of floats, is left to the broadphase.
  if (!representable) {
    forget_kept();
    return;
  }
  // The flags hold kFixed alone here, as EnlargedBoxes reads a non-zero flag as static.
  broadphase_.find_pairs(EnlargedBoxes{enlarged_, flags_}, kept_);
  sort_and_drop_same_body(kept_);
  keeping_ = true;
  served_ = 0;
}

void CandidatePairs::filter_kept() {
  // The broadphase pairs two boxes when, grown by margin / 2, they overlap: each box lies within
  // its enlarged copy, so every such pair is among the kept ones, in the same order.
  const auto overlapping = [this](const ShapePair& p) {
    return grown_[p.first].overlaps(grown_[p.second]);
  };
  const std::size_t n = kept_.size();
  if (n < kParallelCount || one_thread()) {
    pairs_.clear();
    for (const ShapePair& p : kept_) {
      if (overlapping(p)) append(pairs_, p);
    }
    return;
  }
  // Twice over, block by block: counting each block's pairs left, then writing them where the
  // counts before them end.
  const std::size_t blocks = (n + kPerTask - 1) / kPerTask;
  const auto each_block = [&](const auto& work) {
    for_blocks(blocks, 1, false, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        work(k, k * kPerTask, std::min(n, (k + 1) * kPerTask));
      }
    });
  };
  block_counts_.assign(blocks + 1, 0);
  each_block([&](std::size_t k, std::size_t first, std::size_t last) {
    block_counts_[k + 1] = static_cast<std::size_t>(
        std::count_if(kept_.begin() + static_cast<std::ptrdiff_t>(first),
                      kept_.begin() + static_cast<std::ptrdiff_t>(last), overlapping));
  });
  for (std::size_t k = 0; k < blocks; ++k) block_counts_[k + 1] += block_counts_[k];
  reserve_for(pairs_, block_counts_[blocks]);
  pairs_.resize(block_counts_[blocks]);
  each_block([&](std::size_t k, std::size_t first, std::size_t last) {
    std::copy_if(kept_.begin() + static_cast<std::ptrdiff_t>(first),
                 kept_.begin() + static_cast<std::ptrdiff_t>(last),
                 pairs_.begin() + static_cast<std::ptrdiff_t>(block_counts_[k]), overlapping);
  });
}

void CandidatePairs::sort_and_drop_same_body(std::vector<ShapePair>& pairs) {
  // Two parts of one body never collide.
  std::erase_if(pairs,
                [this](const ShapePair& p) { return body_of_[p.first] == body_of_[p.second]; });
  // Sorted pairs make the order of the solver, and so the result, independent of the
  // broadphase's internal order.
  pair_order_.sort(pairs, static_cast<std::uint32_t>(body_of_.size()));
}

void CandidatePairs::release() {
  forget_kept();
  calm_needed_ = kCalmCalls;
  broadphase_.release();
  pairs_ = std::vector<ShapePair>();
  body_of_ = std::vector<BodyId>();
}

void CandidatePairs::forget_kept() {
  keeping_ = false;
  calm_calls_ = 0;
  // Moved-from temporaries take the room with them: a scene on the move holds none of it.
  enlarged_ = std::vector<EnlargedBox>();
  flags_ = std::vector<std::uint8_t>();
  grown_ = std::vector<Aabb>();
  kept_ = std::vector<ShapePair>();
  outside_ = std::vector<std::uint32_t>();
  refreshed_ = std::vector<ShapePair>();
  block_counts_ = std::vector<std::size_t>();
}

}  // namespace gp
