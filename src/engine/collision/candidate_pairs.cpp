#include "engine/collision/candidate_pairs.hpp"

#include <algorithm>
#include <cmath>

#include "engine/capacity.hpp"
#include "engine/collision/swept_boxes.hpp"
#include "engine/threads.hpp"

namespace gp {

namespace {

// At least this many shapes, or kept pairs, are shared out among threads, this many a task: a
// box or a pair costs nanoseconds, handing out a task about a microsecond.
constexpr std::size_t kParallelCount = 4096;
constexpr std::size_t kPerTask = 1024;

// Tells one list of pairs from another, but for a chance of 2⁻⁶⁴; a false match only keeps pairs
// that the next call then finds outgrown.
std::uint64_t fingerprint_of(const std::vector<ShapePair>& pairs) {
  std::uint64_t h = pairs.size();
  for (const ShapePair& p : pairs) {
    h = (h ^ (std::uint64_t{p.first} << 32 | p.second)) * 0x9E3779B97F4A7C15ULL;
    h ^= h >> 29;
  }
  return h;
}

bool holds(const Aabb& outer, const Aabb& inner) {
  return inner.min.x() >= outer.min.x() && inner.min.y() >= outer.min.y() &&
         inner.max.x() <= outer.max.x() && inner.max.y() <= outer.max.y();
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
    if (boxes_within_kept(boxes, same_bodies)) {
      filter_kept();
      used_kept_ = true;
      // Kept pairs that last are a pile at rest: the broadphase's room is freed meanwhile, so
      // that the pile holds little more than it did. Pairs outgrown sooner leave it in place.
      if (++served_ == kFewestServed) broadphase_.release();
      return pairs_;
    }
    if (served_ >= kFewestServed) {
      settle_needed_ = kSettledCalls;
      keep_pairs(boxes);
      if (keeping_) {
        filter_kept();
        return pairs_;
      }
    } else {
      // Outgrown too soon: the bodies are on the move. Wait longer each time before keeping again.
      settle_needed_ = std::min(2 * settle_needed_, kLongestSettling);
      forget_kept();
    }
  }
  broadphase_.find_pairs(boxes, pairs_);
  sort_and_drop_same_body(pairs_);
  const std::uint64_t fingerprint = fingerprint_of(pairs_);
  settled_calls_ = fingerprint == fingerprint_ ? settled_calls_ + 1 : 0;
  fingerprint_ = fingerprint;
  if (settled_calls_ >= settle_needed_) keep_pairs(boxes);
  return pairs_;
}

template <typename Boxes>
bool CandidatePairs::boxes_within_kept(const Boxes& boxes, bool same_bodies) {
  const std::size_t n = boxes.size();
  reserve_for(grown_, n);
  grown_.resize(n);
  const bool comparable = same_bodies && enlarged_.size() == n;
  // Every box grown, for filter_kept or the broadphase, even once one is found outside.
  return reduce_blocks(
      n, kPerTask, n < kParallelCount, true,
      [&](std::size_t first, std::size_t last, bool within) {
        for (auto i = static_cast<std::uint32_t>(first); i < last; ++i) {
          const Aabb box = boxes.bounds(i);
          grown_[i] = box.fattened(half_margin_);
          within = within && comparable && (fixed_[i] != 0) == boxes.is_static(i) &&
                   holds(enlarged_[i].bounds(), box);
        }
        return within;
      },
      [](bool a, bool b) { return a && b; });
}

template <typename Boxes>
void CandidatePairs::keep_pairs(const Boxes& boxes) {
  const std::size_t n = boxes.size();
  reserve_for(enlarged_, n);
  enlarged_.resize(n);
  reserve_for(fixed_, n);
  fixed_.resize(n);
  const bool representable = reduce_blocks(
      n, kPerTask, n < kParallelCount, true,
      [&](std::size_t first, std::size_t last, bool all) {
        for (auto i = static_cast<std::uint32_t>(first); i < last; ++i) {
          const Aabb box = boxes.bounds(i);
          const bool fixed = boxes.is_static(i);
          // A static body's box never moves; a kinematic one's, which moves, finds its kept
          // pairs outgrown at its first move.
          const double slack = fixed ? 0.0 : kSlack * (box.max - box.min).sum();
          const std::optional<EnlargedBox> enlarged = enlarged_box(box.fattened(slack));
          all = all && enlarged.has_value();
          if (enlarged) enlarged_[i] = *enlarged;
          fixed_[i] = fixed ? 1 : 0;
        }
        return all;
      },
      [](bool a, bool b) { return a && b; });
  // A box not finite, or beyond the range of floats, is left to the broadphase.
  if (!representable) {
    forget_kept();
    return;
  }
  broadphase_.find_pairs(EnlargedBoxes{enlarged_, fixed_}, kept_);
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

void CandidatePairs::forget_kept() {
  keeping_ = false;
  settled_calls_ = 0;
  // Moved-from temporaries take the room with them: a scene on the move holds none of it.
  enlarged_ = std::vector<EnlargedBox>();
  fixed_ = std::vector<std::uint8_t>();
  grown_ = std::vector<Aabb>();
  kept_ = std::vector<ShapePair>();
  block_counts_ = std::vector<std::size_t>();
}

}  // namespace gp
