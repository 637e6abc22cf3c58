#include "engine/collision/broadphase.hpp"

#include <algorithm>
#include <cmath>

namespace gp {

const std::vector<ProxyPair>& SweepAndPrune::find_pairs(std::span<const BroadphaseProxy> proxies) {
  pairs_.clear();
  entries_.clear();
  candidates_tested_ = 0;
  if (proxies.empty()) return pairs_;
  // A non-finite box comes from a state that the step reports as non-finite (NumericalError); the
  // band arithmetic below would convert NaN or infinity to an integer, which is undefined. The
  // same holds when the boxes span more than the range of a double.
  const auto finite = [](const BroadphaseProxy& p) {
    return p.bounds.min.allFinite() && p.bounds.max.allFinite();
  };
  if (!std::all_of(proxies.begin(), proxies.end(), finite)) return pairs_;

  // Bands start at the lowest grown bottom. Bands above the highest bottom hold no overlap's
  // bottom, so no box needs entries there.
  band_origin_ = proxies.front().bounds.fattened(half_margin_).min.y();
  double highest_bottom = band_origin_;
  for (const BroadphaseProxy& proxy : proxies) {
    const double bottom = proxy.bounds.fattened(half_margin_).min.y();
    band_origin_ = std::min(band_origin_, bottom);
    highest_bottom = std::max(highest_bottom, bottom);
  }
  if (!std::isfinite(highest_bottom - band_origin_)) return pairs_;
  band_height_ = choose_band_height(proxies, highest_bottom - band_origin_);
  const std::int64_t last_band = band_of(highest_bottom);

  for (const BroadphaseProxy& proxy : proxies) {
    const Aabb grown = proxy.bounds.fattened(half_margin_);
    const std::int64_t top_band = std::min(band_of(grown.max.y()), last_band);
    for (std::int64_t band = band_of(grown.min.y()); band <= top_band; ++band) {
      entries_.push_back({band, grown.min.x(), grown.max.x(), grown.min.y(), grown.max.y(),
                          proxy.id, proxy.is_static});
    }
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return a.band != b.band ? a.band < b.band : a.left < b.left;
  });
  sweep();
  return pairs_;
}

double SweepAndPrune::choose_band_height(std::span<const BroadphaseProxy> proxies,
                                         double bottoms_range) {
  heights_.clear();
  for (const BroadphaseProxy& proxy : proxies) {
    heights_.push_back(proxy.bounds.max.y() - proxy.bounds.min.y() + 2.0 * half_margin_);
  }
  const auto middle = heights_.begin() + static_cast<std::ptrdiff_t>(heights_.size() / 2);
  std::nth_element(heights_.begin(), middle, heights_.end());
  const double height =
      std::max(2.0 * *middle, bottoms_range / static_cast<double>(proxies.size()));
  // Boxes all flat and level: any height gives them one band.
  return height > 0.0 ? height : 1.0;
}

void SweepAndPrune::sweep() {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& entry = entries_[i];
    for (std::size_t j = i + 1;
         j < entries_.size() && entries_[j].band == entry.band && entries_[j].left <= entry.right;
         ++j) {
      const Entry& other = entries_[j];
      ++candidates_tested_;
      if (entry.is_static && other.is_static) continue;
      if (other.bottom > entry.top || entry.bottom > other.top) continue;
      if (band_of(std::max(entry.bottom, other.bottom)) != entry.band) continue;
      pairs_.push_back({std::min(entry.id, other.id), std::max(entry.id, other.id)});
    }
  }
}

}  // namespace gp
