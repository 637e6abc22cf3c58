#include "engine/collision/broadphase.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/capacity.hpp"
#include "engine/collision/enlarged_boxes.hpp"
#include "engine/collision/swept_boxes.hpp"
#include "engine/threads.hpp"

namespace gp {

template <BroadphaseBoxes Boxes>
void SweepAndPrune::find_pairs(const Boxes& boxes, std::vector<ShapePair>& pairs) {
  pairs.clear();
  candidates_tested_ = 0;
  entries_resorted_ = 0;
  const Survey found = survey(boxes);
  if (!found.usable) {
    forget();
    return;
  }
  place_bands(boxes, found);
  update_entries(boxes, found.highest);
  sweep(pairs);
}

template <typename Boxes>
SweepAndPrune::Survey SweepAndPrune::survey(const Boxes& boxes) const {
  if (boxes.size() == 0) return Survey{};
  // One pass, as each box is made when it is read: the bottoms, and the heights that bands_suit
  // weighs against the bands of the last call. `usable` holds whether the boxes are finite until
  // the end; minima, maxima and counts come out the same however the boxes are shared out.
  const double h = band_height_;
  const auto survey_range = [&](std::size_t first, std::size_t last, Survey found) {
    for (auto i = static_cast<std::uint32_t>(first); i < last; ++i) {
      const Aabb box = boxes.bounds(i);
      found.usable = found.usable && box.min.allFinite() && box.max.allFinite();
      const double bottom = box.min.y() - half_margin_;
      found.lowest = std::min(found.lowest, bottom);
      found.highest = std::max(found.highest, bottom);
      const double height = grown_height(box);
      found.up_to_band += height <= h;
      found.below_quarter_band += height < 0.25 * h;
    }
    return found;
  };
  Survey none;
  none.usable = true;
  none.lowest = std::numeric_limits<double>::infinity();
  none.highest = -none.lowest;
  Survey found =
      reduce_blocks(boxes.size(), kBoxesPerTask, boxes.size() < kParallelBoxes, none, survey_range,
                    [](const Survey& a, const Survey& b) {
                      return Survey{a.usable && b.usable, std::min(a.lowest, b.lowest),
                                    std::max(a.highest, b.highest), a.up_to_band + b.up_to_band,
                                    a.below_quarter_band + b.below_quarter_band};
                    });
  // A non-finite box comes from a state that the step reports as non-finite (NumericalError); the
  // band arithmetic would convert NaN or infinity to an integer, which is undefined. The same
  // holds when the boxes span more than the range of a double.
  found.usable = found.usable && std::isfinite(found.highest - found.lowest);
  return found;
}

template <typename Boxes>
double SweepAndPrune::ideal_band_height(const Boxes& boxes, double bottoms_range) const {
  const double height =
      std::max(2.0 * median_height(boxes), bottoms_range / static_cast<double>(boxes.size()));
  // Boxes all flat and level: any height gives them one band.
  return height > 0.0 ? height : 1.0;
}

template <typename Boxes>
double SweepAndPrune::median_height(const Boxes& boxes) const {
  // Found without a copy of the heights to select in, which would be kept as large as the
  // boxes: the heights are ≥ 0 (never -0, as x - x is +0), and such doubles order as their bit
  // patterns do, so a binary search over the patterns finds it in at most 64 passes that count
  // the heights up to a pattern. The bands are placed seldom, so the passes cost little.
  const std::size_t rank = boxes.size() / 2;
  std::uint64_t low = 0;
  std::uint64_t high = std::bit_cast<std::uint64_t>(std::numeric_limits<double>::infinity());
  while (low < high) {
    const std::uint64_t middle = low + (high - low) / 2;
    const double bound = std::bit_cast<double>(middle);
    std::size_t up_to = 0;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
      up_to += grown_height(boxes.bounds(i)) <= bound;
    if (up_to > rank) {
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  return std::bit_cast<double>(low);
}

template <typename Boxes>
void SweepAndPrune::place_bands(const Boxes& boxes, const Survey& survey) {
  if (bands_suit(boxes.size(), survey)) return;
  forget();
  // Bands start a quarter of a band below the lowest grown bottom: a body pressed a little deeper
  // into the ground at every step (the bottom of a settling pile) would otherwise move the bands,
  // and sort every entry afresh, at every step. Bands above the highest bottom hold no overlap's
  // bottom, so no box needs entries there.
  band_height_ = ideal_band_height(boxes, survey.highest - survey.lowest);
  band_origin_ = survey.lowest - 0.25 * band_height_;
}

bool SweepAndPrune::bands_suit(std::size_t count, const Survey& survey) const {
  // Moving the bands moves nearly every entry, which then has to be sorted afresh; bands within a
  // factor of two of the ideal height cost little more to sweep. They must still start at or
  // below the lowest bottom, and hold the bottoms in at most about 2N bands.
  const double h = band_height_;
  const double n = static_cast<double>(count);
  if (!(h > 0.0) || survey.lowest < band_origin_ || survey.highest - band_origin_ > 2.0 * n * h) {
    return false;
  }
  // The ideal is max(2m, range / N) for the median height m: h ≥ ideal / 2 when h ≥ m and
  // h ≥ range / 2N, and h ≤ 2 · ideal when h ≤ 4m or h ≤ 2 · range / N. The boxes no taller
  // than h and those shorter than h / 4 place m against both without finding it.
  const double range = survey.highest - survey.lowest;
  if (h < range / (2.0 * n)) return false;
  // m is the height of rank N / 2 (from 0): m ≤ h when more than N / 2 boxes are no taller than
  // h, and m ≥ h / 4 when at most N / 2 are shorter than h / 4.
  const std::size_t median_rank = count / 2;
  return survey.up_to_band > median_rank &&
         (h <= 2.0 * range / n || survey.below_quarter_band <= median_rank);
}

template <typename Boxes>
void SweepAndPrune::update_entries(const Boxes& boxes, double highest) {
  const std::int64_t last_band = band_of(highest);
  if (entries_.empty()) {
    build_entries(boxes, last_band);
    return;
  }
  // Each box of the last call has exactly one entry in each band of bands_[i]: those of its
  // bands now are kept in place, where they are nearly sorted still. Refreshed where they are,
  // those that left their band marked (band −1, below every band), then the marked dropped.
  const auto refresh = [&](std::size_t first, std::size_t last) {
    for (std::size_t e = first; e < last; ++e) {
      Entry& old = entries_[e];
      const std::uint32_t i = old.box();
      if (i >= boxes.size()) {
        old.band = -1;
        continue;
      }
      const Aabb grown = boxes.bounds(i).fattened(half_margin_);
      const BandRange now = bands_of(grown, last_band);
      if (old.band < now.first || old.band > now.last) {
        old.band = -1;
        continue;
      }
      old = entry(grown, old.band, i, now, boxes.is_static(i));
    }
  };
  for_blocks(entries_.size(), kBoxesPerTask, entries_.size() < kParallelBoxes, refresh);
  std::erase_if(entries_, [](const Entry& e) { return e.band < 0; });
  added_.clear();
  const std::size_t known = bands_.size();
  bands_.resize(boxes.size());
  const auto add_new_bands = [&](std::uint32_t first, std::uint32_t last,
                                 std::vector<Entry>& added) {
    for (std::uint32_t i = first; i < last; ++i) {
      const BandRange before = i < known ? bands_[i] : BandRange{0, -1};
      const Aabb grown = boxes.bounds(i).fattened(half_margin_);
      const BandRange now = bands_of(grown, last_band);
      for (std::int32_t band = now.first; band <= now.last; ++band) {
        if (band < before.first || band > before.last) {
          added.push_back(entry(grown, band, i, now, boxes.is_static(i)));
        }
      }
      bands_[i] = now;
    }
  };
  const auto count = static_cast<std::uint32_t>(boxes.size());
  if (count < kParallelBoxes || one_thread()) {
    add_new_bands(0, count, added_);
  } else {
    // Each thread its own list, gathered in any order: sort_entries sorts them.
    for (auto& local : thread_added_) local.clear();
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, count, kBoxesPerTask),
                      [&](const tbb::blocked_range<std::uint32_t>& r) {
                        add_new_bands(r.begin(), r.end(), thread_added_.local());
                      });
    for (const auto& local : thread_added_) added_.insert(added_.end(), local.begin(), local.end());
  }
  sort_entries();
}

template <typename Boxes>
void SweepAndPrune::build_entries(const Boxes& boxes, std::int64_t last_band) {
  // Straight into entries_, sized to them: going through added_ would keep a second buffer as
  // large as all the entries for the rest of the run.
  bands_.resize(boxes.size());
  std::size_t count = 0;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    bands_[i] = bands_of(boxes.bounds(i).fattened(half_margin_), last_band);
    count += bands_[i].last - bands_[i].first + 1;
  }
  reserve_for(entries_, count);
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    const Aabb grown = boxes.bounds(i).fattened(half_margin_);
    for (std::int32_t band = bands_[i].first; band <= bands_[i].last; ++band) {
      entries_.push_back(entry(grown, band, i, bands_[i], boxes.is_static(i)));
    }
  }
  std::sort(entries_.begin(), entries_.end());
  entries_resorted_ = entries_.size();
}

void SweepAndPrune::sort_entries() {
  // Insertion sort: O(N + moves), and bodies that moved a little make few moves. Past O(N log N)
  // moves the entries were shuffled, and a sort from scratch is cheaper.
  const std::size_t kept = entries_.size();
  const std::size_t move_budget = kept * static_cast<std::size_t>(std::bit_width(kept));
  std::size_t moves = 0;
  for (std::size_t i = 1; i < kept; ++i) {
    if (!(entries_[i] < entries_[i - 1])) continue;
    const Entry moving = entries_[i];
    std::size_t j = i;
    do {
      entries_[j] = entries_[j - 1];
      --j;
    } while (j > 0 && moving < entries_[j - 1]);
    entries_[j] = moving;
    moves += i - j;
    if (moves > move_budget) {
      std::sort(entries_.begin(), entries_.end());
      entries_resorted_ = kept;
      break;
    }
  }
  // The added entries, sorted, merge in from the back: only the kept ones after the first of them
  // move.
  std::sort(added_.begin(), added_.end());
  entries_resorted_ += added_.size();
  reserve_for(entries_, kept + added_.size());
  entries_.resize(kept + added_.size());
  std::size_t from_kept = kept;
  std::size_t from_added = added_.size();
  std::size_t to = entries_.size();
  while (from_added > 0) {
    if (from_kept > 0 && added_[from_added - 1] < entries_[from_kept - 1]) {
      entries_[--to] = entries_[--from_kept];
    } else {
      entries_[--to] = added_[--from_added];
    }
  }
}

namespace {

// Calls `pair(a, b)` for each pair of `entries` from entries[first] to entries[last − 1] with
// the entries after them in their band, a < b; returns how many candidates it compared.
template <typename Entry, typename Pair>
std::size_t sweep_entries(std::span<const Entry> entries, std::size_t first, std::size_t last,
                          const Pair& pair) {
  std::size_t tested = 0;
  for (std::size_t i = first; i < last; ++i) {
    const Entry& entry = entries[i];
    for (std::size_t j = i + 1;
         j < entries.size() && entries[j].band == entry.band && entries[j].left <= entry.right;
         ++j) {
      const Entry& other = entries[j];
      ++tested;
      if (entry.has(Entry::kStatic) && other.has(Entry::kStatic)) continue;
      if (other.bottom > entry.top || entry.bottom > other.top) continue;
      if (!entry.has(Entry::kBottom) && !other.has(Entry::kBottom)) continue;
      const std::uint32_t a = entry.box();
      const std::uint32_t b = other.box();
      pair(std::min(a, b), std::max(a, b));
    }
  }
  return tested;
}

}  // namespace

void SweepAndPrune::sweep(std::vector<ShapePair>& pairs) {
  // The entries in a local: pairs growing might, for all the compiler knows, change the members,
  // which it would then reload at every candidate.
  const std::span<const Entry> entries(entries_);
  if (entries.size() < kParallelBoxes || one_thread()) {
    candidates_tested_ =
        sweep_entries(entries, 0, entries.size(), [&](std::uint32_t a, std::uint32_t b) {
          append(pairs, {a, b});
        });
    return;
  }
  // Twice over, block by block: counting each block's pairs, then writing them where the counts
  // before them end. Lists per thread would keep room for the pairs again, on every thread.
  const std::size_t blocks = (entries.size() + kBoxesPerTask - 1) / kBoxesPerTask;
  const auto each_block = [&](const auto& work) {
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t k) {
      work(k, k * kBoxesPerTask, std::min(entries.size(), (k + 1) * kBoxesPerTask));
    });
  };
  block_pairs_.assign(blocks + 1, 0);
  block_tested_.resize(blocks);
  each_block([&](std::size_t k, std::size_t first, std::size_t last) {
    std::size_t count = 0;
    block_tested_[k] =
        sweep_entries(entries, first, last, [&count](std::uint32_t, std::uint32_t) { ++count; });
    block_pairs_[k + 1] = count;
  });
  for (std::size_t k = 0; k < blocks; ++k) block_pairs_[k + 1] += block_pairs_[k];
  reserve_for(pairs, block_pairs_[blocks]);
  pairs.resize(block_pairs_[blocks]);
  each_block([&](std::size_t k, std::size_t first, std::size_t last) {
    std::size_t at = block_pairs_[k];
    sweep_entries(entries, first, last, [&](std::uint32_t a, std::uint32_t b) {
      pairs[at++] = {a, b};
    });
  });
  candidates_tested_ = 0;
  for (std::size_t k = 0; k < blocks; ++k) candidates_tested_ += block_tested_[k];
}

void SweepAndPrune::forget() {
  entries_.clear();
  bands_.clear();
  band_height_ = 0.0;
}

void SweepAndPrune::release() {
  forget();
  // Moved-from temporaries take the room with them.
  entries_ = std::vector<Entry>();
  bands_ = std::vector<BandRange>();
  added_ = std::vector<Entry>();
  thread_added_.clear();
  block_pairs_ = std::vector<std::size_t>();
  block_tested_ = std::vector<std::size_t>();
}

template void SweepAndPrune::find_pairs(const ProxyBoxes&, std::vector<ShapePair>&);
template void SweepAndPrune::find_pairs(const EnlargedBoxes&, std::vector<ShapePair>&);
template void SweepAndPrune::find_pairs(const SweptBoxes&, std::vector<ShapePair>&);

}  // namespace gp
