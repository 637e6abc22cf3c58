#include "engine/collision/pair_order.hpp"

#include <algorithm>

#include "engine/capacity.hpp"

namespace gp {

namespace {

// One stable counting-sort pass of `in` into `out` by the id `digit` picks.
template <typename Digit>
void counting_pass(const std::vector<ShapePair>& in, std::vector<ShapePair>& out,
                   std::vector<std::uint32_t>& starts, Digit digit) {
  std::fill(starts.begin(), starts.end(), 0u);
  for (const ShapePair& p : in) ++starts[digit(p) + 1];
  for (std::size_t id = 1; id < starts.size(); ++id) starts[id] += starts[id - 1];
  reserve_for(out, in.size());
  out.resize(in.size());
  for (const ShapePair& p : in) out[starts[digit(p)]++] = p;
}

}  // namespace

void PairOrder::sort(std::vector<ShapePair>& pairs, std::uint32_t id_bound) {
  starts_.resize(std::size_t{id_bound} + 1);
  // Least significant digit first: the second pass, being stable, keeps each first id's pairs in
  // the order of their second ids.
  counting_pass(pairs, scratch_, starts_, [](const ShapePair& p) { return p.second; });
  counting_pass(scratch_, pairs, starts_, [](const ShapePair& p) { return p.first; });
}

}  // namespace gp
