#include "engine/collision/pair_order.hpp"

#include <algorithm>
#include <utility>

namespace gp {

void PairOrder::sort(std::vector<ProxyPair>& pairs, std::uint32_t id_bound) {
  buckets_.resize(id_bound);
  for (Bucket& bucket : buckets_) bucket.end = 0;
  for (const ProxyPair& p : pairs) ++buckets_[p.first].end;
  std::uint32_t start = 0;
  for (Bucket& bucket : buckets_) {
    bucket.next = start;
    start += bucket.end;
    bucket.end = start;
  }
  // In place, bucket by bucket: a pair of another first id goes to the next free slot of its own
  // bucket, and the one it displaces in turn to its own, until one of this bucket comes back to
  // fill the slot. The buckets before this one are full, so every pair left belongs here or after.
  std::uint32_t begin = 0;
  for (std::uint32_t id = 0; id < id_bound; ++id) {
    Bucket& bucket = buckets_[id];
    while (bucket.next < bucket.end) {
      ProxyPair moving = pairs[bucket.next];
      while (moving.first != id) std::swap(moving, pairs[buckets_[moving.first].next++]);
      pairs[bucket.next++] = moving;
    }
    sort_by_second(std::span(pairs).subspan(begin, bucket.end - begin));
    begin = bucket.end;
  }
}

void PairOrder::sort_by_second(std::span<ProxyPair> pairs) {
  const auto by_second = [](const ProxyPair& a, const ProxyPair& b) { return a.second < b.second; };
  // Most shapes are the first of a few pairs, sorted here by insertion without std::sort's call;
  // a ground or a wall may be the first of many.
  constexpr std::size_t kFew = 16;
  if (pairs.size() > kFew) {
    std::sort(pairs.begin(), pairs.end(), by_second);
    return;
  }
  for (std::size_t i = 1; i < pairs.size(); ++i) {
    const ProxyPair moving = pairs[i];
    std::size_t j = i;
    for (; j > 0 && by_second(moving, pairs[j - 1]); --j) pairs[j] = pairs[j - 1];
    pairs[j] = moving;
  }
}

}  // namespace gp
