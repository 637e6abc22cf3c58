// The order of candidate pairs that makes the solver's order independent of the broadphase.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "engine/collision/pair_order.hpp"

using gp::ShapePair;

namespace {
namespace test_pair_order {

TEST_CASE("Pair order sorts pairs by first id, then second, as a comparison sort does",
          "[FR:Determine-Collisions]") {
  std::mt19937 random(17);
  for (const std::uint32_t bound : {1u, 2u, 7u, 300u, 5000u}) {
    std::uniform_int_distribution<std::uint32_t> id(0, bound - 1);
    std::vector<ShapePair> pairs;
    for (int i = 0; i < 3000; ++i) {
      const std::uint32_t a = id(random);
      const std::uint32_t b = id(random);
      pairs.push_back({std::min(a, b), std::max(a, b)});
    }
    std::vector<ShapePair> expected = pairs;
    std::sort(expected.begin(), expected.end());
    gp::PairOrder order;
    order.sort(pairs, bound);
    INFO("ids below " << bound);
    CHECK(pairs == expected);
  }
}

TEST_CASE("Pair order keeps its buffers and handles no pairs", "[FR:Determine-Collisions]") {
  gp::PairOrder order;
  std::vector<ShapePair> pairs;
  order.sort(pairs, 10);
  CHECK(pairs.empty());
  pairs = {{3, 9}, {0, 4}, {3, 4}, {0, 1}};
  order.sort(pairs, 10);
  CHECK(pairs == std::vector<ShapePair>{{0, 1}, {0, 4}, {3, 4}, {3, 9}});
  pairs = {{2, 5}, {1, 2}, {1, 8}, {0, 3}};
  pairs.reserve(16);
  const ShapePair* buffer = pairs.data();
  order.sort(pairs, 10);
  CHECK(pairs == std::vector<ShapePair>{{0, 3}, {1, 2}, {1, 8}, {2, 5}});
  CHECK(pairs.data() == buffer);
}

}  // namespace test_pair_order
}  // namespace
