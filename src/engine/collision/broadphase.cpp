#include "engine/collision/broadphase.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "engine/capacity.hpp"

namespace gp {

void SweepAndPrune::find_pairs(std::span<const BroadphaseProxy> proxies,
                               std::vector<ProxyPair>& pairs) {
  pairs.clear();
  candidates_tested_ = 0;
  entries_resorted_ = 0;
  // A non-finite box comes from a state that the step reports as non-finite (NumericalError); the
  // band arithmetic below would convert NaN or infinity to an integer, which is undefined. The
  // same holds when the boxes span more than the range of a double.
  const auto finite = [](const BroadphaseProxy& p) {
    return p.bounds.min.allFinite() && p.bounds.max.allFinite();
  };
  if (proxies.empty() || !std::all_of(proxies.begin(), proxies.end(), finite)) {
    forget();
    return;
  }
  double lowest = proxies.front().bounds.min.y() - half_margin_;
  double highest = lowest;
  for (const BroadphaseProxy& proxy : proxies) {
    const double bottom = proxy.bounds.min.y() - half_margin_;
    lowest = std::min(lowest, bottom);
    highest = std::max(highest, bottom);
  }
  if (!std::isfinite(highest - lowest)) {
    forget();
    return;
  }
  place_bands(proxies, lowest, highest);
  update_entries(proxies, highest);
  sweep(proxies, pairs);
}

double SweepAndPrune::ideal_band_height(std::span<const BroadphaseProxy> proxies,
                                        double bottoms_range) const {
  const double height =
      std::max(2.0 * median_height(proxies), bottoms_range / static_cast<double>(proxies.size()));
  // Boxes all flat and level: any height gives them one band.
  return height > 0.0 ? height : 1.0;
}

double SweepAndPrune::median_height(std::span<const BroadphaseProxy> proxies) const {
  // Found without a copy of the heights to select in, which would be kept as large as the
  // proxies: the heights are ≥ 0 (never -0, as x - x is +0), and such doubles order as their bit
  // patterns do, so a binary search over the patterns finds it in at most 64 passes that count
  // the heights up to a pattern. The bands are placed seldom, so the passes cost little.
  const std::size_t rank = proxies.size() / 2;
  std::uint64_t low = 0;
  std::uint64_t high = std::bit_cast<std::uint64_t>(std::numeric_limits<double>::infinity());
  while (low < high) {
    const std::uint64_t middle = low + (high - low) / 2;
    const double bound = std::bit_cast<double>(middle);
    std::size_t up_to = 0;
    for (const BroadphaseProxy& proxy : proxies) up_to += grown_height(proxy) <= bound;
    if (up_to > rank) {
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  return std::bit_cast<double>(low);
}

void SweepAndPrune::place_bands(std::span<const BroadphaseProxy> proxies, double lowest,
                                double highest) {
  if (bands_suit(proxies, lowest, highest)) return;
  forget();
  // Bands start at the lowest grown bottom. Bands above the highest bottom hold no overlap's
  // bottom, so no box needs entries there.
  band_origin_ = lowest;
  band_height_ = ideal_band_height(proxies, highest - lowest);
}

bool SweepAndPrune::bands_suit(std::span<const BroadphaseProxy> proxies, double lowest,
                               double highest) const {
  // Moving the bands moves nearly every entry, which then has to be sorted afresh; bands within a
  // factor of two of the ideal height cost little more to sweep. They must still start at or
  // below the lowest bottom, and hold the bottoms in at most about 2N bands.
  const double h = band_height_;
  const double count = static_cast<double>(proxies.size());
  if (!(h > 0.0) || lowest < band_origin_ || highest - band_origin_ > 2.0 * count * h) {
    return false;
  }
  // The ideal is max(2m, range / N) for the median height m: h ≥ ideal / 2 when h ≥ m and
  // h ≥ range / 2N, and h ≤ 2 · ideal when h ≤ 4m or h ≤ 2 · range / N. Counting the boxes no
  // taller than h and those shorter than h / 4 places m against both without finding it.
  const double range = highest - lowest;
  if (h < range / (2.0 * count)) return false;
  std::size_t up_to_h = 0;
  std::size_t below_quarter_h = 0;
  for (const BroadphaseProxy& proxy : proxies) {
    const double height = grown_height(proxy);
    up_to_h += height <= h;
    below_quarter_h += height < 0.25 * h;
  }
  // m is the height of rank N / 2 (from 0): m ≤ h when more than N / 2 boxes are no taller than
  // h, and m ≥ h / 4 when at most N / 2 are shorter than h / 4.
  const std::size_t median_rank = proxies.size() / 2;
  return up_to_h > median_rank && (h <= 2.0 * range / count || below_quarter_h <= median_rank);
}

SweepAndPrune::Entry SweepAndPrune::entry(std::span<const BroadphaseProxy> proxies,
                                          std::int32_t band, std::uint32_t p) const {
  const Aabb grown = proxies[p].bounds.fattened(half_margin_);
  return Entry{grown.min.x(),
               grown.max.x(),
               grown.min.y(),
               grown.max.y(),
               band,
               p << 2 | (proxies[p].is_static ? Entry::kStatic : 0) |
                   (band == new_bands_[p].first ? Entry::kBottom : 0)};
}

void SweepAndPrune::update_entries(std::span<const BroadphaseProxy> proxies, double highest) {
  const std::int64_t last_band = band_of(highest);
  new_bands_.resize(proxies.size());
  for (std::size_t p = 0; p < proxies.size(); ++p) {
    const Aabb grown = proxies[p].bounds.fattened(half_margin_);
    // Between 0 (no bottom is below the origin) and last_band, which 32 bits hold.
    new_bands_[p] = {static_cast<std::int32_t>(band_of(grown.min.y())),
                     static_cast<std::int32_t>(std::min(band_of(grown.max.y()), last_band))};
  }
  if (entries_.empty()) {
    build_entries(proxies);
    return;
  }
  // Each proxy of the last call has exactly one entry in each band of bands_[p]: those of its
  // bands now are kept in place, where they are nearly sorted still.
  std::size_t kept = 0;
  for (const Entry& old : entries_) {
    if (old.proxy() >= proxies.size()) continue;
    const BandRange& now = new_bands_[old.proxy()];
    if (old.band < now.first || old.band > now.last) continue;
    entries_[kept++] = entry(proxies, old.band, old.proxy());
  }
  entries_.resize(kept);
  added_.clear();
  for (std::uint32_t p = 0; p < proxies.size(); ++p) {
    const BandRange before = p < bands_.size() ? bands_[p] : BandRange{0, -1};
    const BandRange& now = new_bands_[p];
    for (std::int32_t band = now.first; band <= now.last; ++band) {
      if (band < before.first || band > before.last) added_.push_back(entry(proxies, band, p));
    }
  }
  bands_.swap(new_bands_);
  sort_entries();
}

void SweepAndPrune::build_entries(std::span<const BroadphaseProxy> proxies) {
  // Straight into entries_, sized to them: going through added_ would keep a second buffer as
  // large as all the entries for the rest of the run.
  std::size_t count = 0;
  for (const BandRange& bands : new_bands_) count += bands.last - bands.first + 1;
  reserve_for(entries_, count);
  for (std::uint32_t p = 0; p < proxies.size(); ++p) {
    for (std::int32_t band = new_bands_[p].first; band <= new_bands_[p].last; ++band) {
      entries_.push_back(entry(proxies, band, p));
    }
  }
  std::sort(entries_.begin(), entries_.end());
  entries_resorted_ = entries_.size();
  bands_.swap(new_bands_);
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

void SweepAndPrune::sweep(std::span<const BroadphaseProxy> proxies, std::vector<ProxyPair>& pairs) {
  // The entries and the count in locals: pairs growing might, for all the compiler knows, change
  // the members, which it would then reload at every candidate.
  const std::span<const Entry> entries(entries_);
  std::size_t tested = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const Entry& entry = entries[i];
    for (std::size_t j = i + 1;
         j < entries.size() && entries[j].band == entry.band && entries[j].left <= entry.right;
         ++j) {
      const Entry& other = entries[j];
      ++tested;
      if (entry.has(Entry::kStatic) && other.has(Entry::kStatic)) continue;
      if (other.bottom > entry.top || entry.bottom > other.top) continue;
      if (!entry.has(Entry::kBottom) && !other.has(Entry::kBottom)) continue;
      const std::uint32_t a = proxies[entry.proxy()].id;
      const std::uint32_t b = proxies[other.proxy()].id;
      append(pairs, {std::min(a, b), std::max(a, b)});
    }
  }
  candidates_tested_ = tested;
}

void SweepAndPrune::forget() {
  entries_.clear();
  bands_.clear();
  band_height_ = 0.0;
}

}  // namespace gp
