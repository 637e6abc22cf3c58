// Sweep-and-prune broadphase against all-pairs testing (FR:Determine-Collisions).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include "engine/collision/broadphase.hpp"

using gp::Aabb;
using gp::BroadphaseProxy;
using gp::ShapePair;
using gp::Vec2;

namespace {
namespace test_broadphase {

/// Each proxy's box fattened by half the margin: the boxes whose overlaps make pairs.
std::vector<Aabb> fattened_bounds(const std::vector<BroadphaseProxy>& proxies, double margin) {
  std::vector<Aabb> fattened;
  for (const BroadphaseProxy& proxy : proxies)
    fattened.push_back(proxy.bounds.fattened(0.5 * margin));
  return fattened;
}

/// Whether the broadphase should report proxies i < j: not both static, and their fattened boxes
/// overlap.
bool should_pair(const std::vector<BroadphaseProxy>& proxies, const std::vector<Aabb>& fattened,
                 std::size_t i, std::size_t j) {
  return !(proxies[i].is_static && proxies[j].is_static) && fattened[i].overlaps(fattened[j]);
}

/// Every pair the broadphase should report, by testing all N² / 2 pairs.
std::vector<ShapePair> all_overlapping_pairs(const std::vector<BroadphaseProxy>& proxies,
                                             double margin) {
  const std::vector<Aabb> fattened = fattened_bounds(proxies, margin);
  std::vector<ShapePair> pairs;
  for (std::size_t i = 0; i < proxies.size(); ++i) {
    for (std::size_t j = i + 1; j < proxies.size(); ++j) {
      if (should_pair(proxies, fattened, i, j)) {
        pairs.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

/// `pairs`, all-pairs testing's pairs before proxy `moved` moved, made all-pairs testing's pairs
/// after: its pairs dropped, then each of the N − 1 pairs with it tested again.
void retest_pairs_of(std::vector<ShapePair>& pairs, const std::vector<BroadphaseProxy>& proxies,
                     std::size_t moved, double margin) {
  const std::vector<Aabb> fattened = fattened_bounds(proxies, margin);
  std::erase_if(pairs,
                [moved](const ShapePair& p) { return p.first == moved || p.second == moved; });
  for (std::size_t other = 0; other < proxies.size(); ++other) {
    const std::size_t i = std::min(moved, other);
    const std::size_t j = std::max(moved, other);
    if (i != j && should_pair(proxies, fattened, i, j)) {
      pairs.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

/// Whether fattened boxes `a` and `b` overlap once each side is allowed a float's rounding: the
/// broadphase keeps its boxes' sides as floats rounded outwards, each within 2⁻²² of its
/// coordinate (a few float steps), so two facing sides within twice that of the larger.
bool within_float_rounding(const Aabb& a, const Aabb& b) {
  const double scale = std::max({std::abs(a.min.x()), std::abs(a.min.y()), std::abs(a.max.x()),
                                 std::abs(a.max.y()), std::abs(b.min.x()), std::abs(b.min.y()),
                                 std::abs(b.max.x()), std::abs(b.max.y())});
  return a.fattened(std::ldexp(scale, -21)).overlaps(b);
}

/// Whether `found` (sorted) is what the broadphase promises for `proxies` fattened by half the
/// margin: each pair once, every pair of `overlapping` (all-pairs testing's), and besides them
/// only pairs, not both static, whose boxes overlap within the float rounding of their sides.
bool as_promised(const std::vector<ShapePair>& found, const std::vector<ShapePair>& overlapping,
                 const std::vector<BroadphaseProxy>& proxies, double margin) {
  if (std::adjacent_find(found.begin(), found.end()) != found.end()) return false;
  if (!std::includes(found.begin(), found.end(), overlapping.begin(), overlapping.end())) {
    return false;
  }
  const std::vector<Aabb> fattened = fattened_bounds(proxies, margin);
  return std::all_of(found.begin(), found.end(), [&](const ShapePair& p) {
    return !(proxies[p.first].is_static && proxies[p.second].is_static) &&
           within_float_rounding(fattened[p.first], fattened[p.second]);
  });
}
bool as_promised(const std::vector<ShapePair>& found, const std::vector<BroadphaseProxy>& proxies,
                 double margin) {
  return as_promised(found, all_overlapping_pairs(proxies, margin), proxies, margin);
}

std::vector<ShapePair> sorted(std::vector<ShapePair> pairs) {
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<ShapePair> pairs_found(gp::SweepAndPrune& broadphase,
                                   const std::vector<BroadphaseProxy>& proxies) {
  std::vector<ShapePair> pairs;
  broadphase.find_pairs(proxies, pairs);
  return pairs;
}

BroadphaseProxy box_proxy(const Vec2& center, const Vec2& size, bool is_static) {
  return {Aabb{center - 0.5 * size, center + 0.5 * size}, is_static};
}

// `count` unit boxes of dynamic bodies at random in a square `width` m wide, the same for a given
// `seed`.
std::vector<BroadphaseProxy> random_unit_boxes(std::uint32_t count, double width, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> position(0.0, width);
  std::vector<BroadphaseProxy> proxies;
  for (std::uint32_t i = 0; i < count; ++i) {
    proxies.push_back(box_proxy({position(random), position(random)}, {1.0, 1.0}, false));
  }
  return proxies;
}

TEST_CASE("Sweep and prune finds the same pairs as testing all pairs of 1000 random boxes",
          "[FR:Determine-Collisions]") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> position(0.0, 100.0);
  std::uniform_real_distribution<double> size(0.1, 4.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<BroadphaseProxy> proxies;
  for (int i = 0; i < 1000; ++i) {
    proxies.push_back(box_proxy({position(random), position(random)}, {size(random), size(random)},
                                unit(random) < 0.2));
  }
  const double margin = 0.1;
  gp::SweepAndPrune broadphase(margin);

  const std::vector<ShapePair> first = sorted(pairs_found(broadphase, proxies));
  const std::vector<ShapePair> expected = all_overlapping_pairs(proxies, margin);
  CHECK(expected.size() > 100);  // the scene does have overlaps to find
  CHECK(as_promised(first, expected, proxies, margin));

  SECTION("after a small move") {
    std::normal_distribution<double> jiggle(0.0, 0.05);
    for (BroadphaseProxy& proxy : proxies) {
      if (proxy.is_static) continue;
      const Vec2 move(jiggle(random), jiggle(random));
      proxy.bounds = {proxy.bounds.min + move, proxy.bounds.max + move};
    }
    CHECK(as_promised(sorted(pairs_found(broadphase, proxies)), proxies, margin));
  }
  SECTION("after the proxies were given in another order") {
    std::shuffle(proxies.begin(), proxies.end(), random);
    CHECK(as_promised(sorted(pairs_found(broadphase, proxies)), proxies, margin));
  }
  SECTION("after proxies were removed") {
    proxies.resize(600);
    CHECK(as_promised(sorted(pairs_found(broadphase, proxies)), proxies, margin));
  }
}

TEST_CASE("Sweep and prune kept from step to step finds the pairs of all-pairs testing",
          "[FR:Determine-Collisions]") {
  // Boxes drifting, growing and shrinking (so that they enter and leave bands), some static,
  // proxies removed and added, all grown at once: the entries repaired from the last step must give
  // every overlapping pair exactly once at every step, as a fresh sweep does.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> position(0.0, 60.0);
  std::uniform_real_distribution<double> size(0.2, 3.0);
  std::uniform_real_distribution<double> speed(-0.3, 0.3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  struct Mover {
    Vec2 center;
    Vec2 size;
    Vec2 velocity;
    bool is_static;
  };
  const auto make_mover = [&] {
    const bool is_static = unit(random) < 0.2;
    return Mover{{position(random), position(random)},
                 {size(random), size(random)},
                 is_static ? Vec2::Zero() : Vec2(speed(random), speed(random)),
                 is_static};
  };
  std::vector<Mover> movers(500);
  std::generate(movers.begin(), movers.end(), make_mover);
  const double margin = 0.1;
  gp::SweepAndPrune broadphase(margin);
  std::size_t repaired_steps = 0;
  const int steps = 300;
  for (int step = 0; step < steps; ++step) {
    if (step % 60 == 30) movers.resize(movers.size() - 40);
    if (step % 60 == 59) std::generate_n(std::back_inserter(movers), 70, make_mover);
    // Boxes four times as tall no longer suit the bands: they are placed anew.
    if (step == 150) {
      for (Mover& m : movers) m.size *= 4.0;
    }
    std::vector<BroadphaseProxy> proxies;
    for (std::uint32_t i = 0; i < movers.size(); ++i) {
      Mover& m = movers[i];
      m.center += m.velocity;
      // Back into the square: the scene stays as crowded.
      for (int axis = 0; axis < 2; ++axis) {
        if (m.center[axis] < 0.0 || m.center[axis] > 60.0) m.velocity[axis] = -m.velocity[axis];
      }
      const double breathing = 1.0 + 0.5 * std::sin(0.1 * step + i);
      proxies.push_back(box_proxy(m.center, {m.size.x(), breathing * m.size.y()}, m.is_static));
    }
    const std::vector<ShapePair> found = sorted(pairs_found(broadphase, proxies));
    INFO("step " << step);
    REQUIRE(as_promised(found, proxies, margin));
    if (broadphase.entries_resorted() < proxies.size() / 4) ++repaired_steps;
  }
  // The steps were mostly repairs, not rebuilds: the path under test is the incremental one.
  CHECK(repaired_steps > steps * 9 / 10);
}

TEST_CASE("Sweep and prune shared out among two threads finds the pairs of one thread",
          "[FR:Determine-Collisions]") {
  // 6000 drifting boxes: past the 4096 from which the survey, the entries' repair, the new bands'
  // entries and the sweep are shared out. Each step's pairs must be those of one thread, and at the
  // first and last steps those of all-pairs testing.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> speed(-0.05, 0.05);
  std::vector<BroadphaseProxy> proxies = random_unit_boxes(6000, 120.0, 5);
  std::vector<Vec2> velocity(proxies.size());
  for (Vec2& v : velocity) v = {speed(random), speed(random)};
  const double margin = 0.1;
  gp::SweepAndPrune alone(margin);
  gp::SweepAndPrune shared(margin);
  tbb::task_arena one(1);
  tbb::task_arena two(2);
  const int steps = 30;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < proxies.size(); ++i) {
      proxies[i].bounds.min += velocity[i];
      proxies[i].bounds.max += velocity[i];
    }
    const auto by_one = one.execute([&] { return sorted(pairs_found(alone, proxies)); });
    const auto by_two = two.execute([&] { return sorted(pairs_found(shared, proxies)); });
    INFO("step " << step);
    REQUIRE(by_two == by_one);
    if (step == 0 || step == steps - 1) REQUIRE(as_promised(by_two, proxies, margin));
  }
}

TEST_CASE("Sweep and prune sorts afresh when the boxes were shuffled since the last call",
          "[FR:Determine-Collisions]") {
  // Mirrored left to right, the boxes keep their bands but reverse their order in each: repairing
  // that order by insertion would take O(N²) moves.
  std::vector<BroadphaseProxy> proxies = random_unit_boxes(2000, 30.0, 5);
  gp::SweepAndPrune broadphase(0.0);
  pairs_found(broadphase, proxies);
  CHECK(broadphase.entries_resorted() >= proxies.size());  // the first call has nothing to repair
  pairs_found(broadphase, proxies);
  CHECK(broadphase.entries_resorted() == 0);  // nothing moved
  for (BroadphaseProxy& proxy : proxies) {
    proxy.bounds = Aabb{{-proxy.bounds.max.x(), proxy.bounds.min.y()},
                        {-proxy.bounds.min.x(), proxy.bounds.max.y()}};
  }
  CHECK(as_promised(sorted(pairs_found(broadphase, proxies)), proxies, 0.0));
  CHECK(broadphase.entries_resorted() >= proxies.size());
}

TEST_CASE("A box sinking a millimetre at every call leaves the bands where they are",
          "[FR:Determine-Collisions]") {
  // The bottom of a settling pile, pressed a little deeper into the ground at every step: bands
  // that started at the lowest bottom itself would be placed, and every entry sorted, anew each
  // time.
  std::vector<BroadphaseProxy> proxies = random_unit_boxes(2000, 30.0, 7);
  const auto lowest = std::min_element(proxies.begin(), proxies.end(),
                                       [](const BroadphaseProxy& a, const BroadphaseProxy& b) {
                                         return a.bounds.min.y() < b.bounds.min.y();
                                       });
  gp::SweepAndPrune broadphase(0.0);
  pairs_found(broadphase, proxies);
  // All-pairs testing's pairs, kept up to date by testing the moving box's N − 1 pairs at each
  // call: all N² / 2 pairs at each of 100 calls took 30 s in the coverage and sanitizer builds.
  std::vector<ShapePair> expected = all_overlapping_pairs(proxies, 0.0);
  const auto moved = static_cast<std::size_t>(lowest - proxies.begin());
  int sorted_afresh = 0;
  for (int call = 0; call < 100; ++call) {
    lowest->bounds.min.y() -= 0.001;
    lowest->bounds.max.y() -= 0.001;
    const std::vector<ShapePair> found = sorted(pairs_found(broadphase, proxies));
    retest_pairs_of(expected, proxies, moved, 0.0);
    INFO("call " << call);
    REQUIRE(as_promised(found, expected, proxies, 0.0));
    if (broadphase.entries_resorted() >= proxies.size()) ++sorted_afresh;
  }
  CHECK(sorted_afresh == 0);
  CHECK(expected == all_overlapping_pairs(proxies, 0.0));  // the reference kept up to date
}

TEST_CASE("Sweep and prune finds the pairs of a tall stack", "[FR:Determine-Collisions]") {
  // All boxes share one x interval, so a sweep along x alone would compare every pair.
  std::vector<BroadphaseProxy> proxies{box_proxy({0.0, -0.5}, {20.0, 1.0}, true)};
  for (std::uint32_t level = 0; level < 200; ++level) {
    proxies.push_back(box_proxy({0.01 * (level % 3), 0.5 + level}, {1.0, 1.0}, false));
  }
  gp::SweepAndPrune broadphase(0.0);
  const std::vector<ShapePair> pairs = sorted(pairs_found(broadphase, proxies));
  CHECK(broadphase.candidates_tested() < 4 * proxies.size());
  CHECK(pairs.size() == 200);  // each box touches the one below it (touching counts)
  CHECK(as_promised(pairs, proxies, 0.0));
}

TEST_CASE("Sweep and prune compares a few candidates per box in a scene spread both ways",
          "[FR:Determine-Collisions]") {
  // 40 000 unit boxes at random in a square 400 m wide: a sweep along x alone would compare each
  // with the √N / 2 = 100 boxes sharing its x interval.
  const std::vector<BroadphaseProxy> proxies = random_unit_boxes(40000, 400.0, 3);
  gp::SweepAndPrune broadphase(0.05);
  const std::size_t pairs = pairs_found(broadphase, proxies).size();
  CHECK(pairs > 0);
  CHECK(broadphase.candidates_tested() < 8 * proxies.size());
}

TEST_CASE("A huge box makes no more band entries than there are boxes",
          "[FR:Determine-Collisions]") {
  std::vector<BroadphaseProxy> proxies{box_proxy({0.0, 0.0}, {1e9, 1e9}, true)};
  for (std::uint32_t i = 1; i <= 100; ++i) {
    proxies.push_back(box_proxy({1.5 * i, 2.0 * (i % 7)}, {1.0, 1.0}, false));
  }
  gp::SweepAndPrune broadphase(0.0);
  const std::vector<ShapePair> pairs = sorted(pairs_found(broadphase, proxies));
  CHECK(as_promised(pairs, proxies, 0.0));
  CHECK(broadphase.candidates_tested() < 2 * proxies.size());
}

TEST_CASE("Two static proxies are never paired", "[FR:Determine-Collisions]") {
  std::vector<BroadphaseProxy> proxies;
  for (std::uint32_t i = 0; i < 50; ++i) {
    proxies.push_back(box_proxy({0.1 * i, 0.0}, {2.0, 2.0}, i % 2 == 0));
  }
  gp::SweepAndPrune broadphase(0.0);
  const std::vector<ShapePair>& pairs = pairs_found(broadphase, proxies);
  CHECK_FALSE(pairs.empty());
  for (const ShapePair& pair : pairs) {
    CHECK_FALSE((proxies[pair.first].is_static && proxies[pair.second].is_static));
  }
  for (BroadphaseProxy& proxy : proxies) proxy.is_static = true;
  CHECK(pairs_found(broadphase, proxies).empty());
}

TEST_CASE("Boxes apart by up to the margin are paired", "[FR:Determine-Collisions]") {
  const std::vector<BroadphaseProxy> proxies{box_proxy({0.0, 0.0}, {1.0, 1.0}, false),
                                             box_proxy({1.09, 0.3}, {1.0, 1.0}, false)};
  gp::SweepAndPrune wide(0.1);
  REQUIRE(pairs_found(wide, proxies).size() == 1);
  CHECK(pairs_found(wide, proxies)[0] == ShapePair{0, 1});
  gp::SweepAndPrune narrow(0.08);
  CHECK(pairs_found(narrow, proxies).empty());
}

TEST_CASE("A warmed-up sweep and prune reuses the pair buffer it is given",
          "[FR:Determine-Collisions]") {
  std::vector<BroadphaseProxy> proxies;
  for (std::uint32_t i = 0; i < 100; ++i) {
    proxies.push_back(box_proxy({0.9 * i, 0.0}, {1.0, 1.0}, false));
  }
  gp::SweepAndPrune broadphase(0.0);
  std::vector<ShapePair> pairs;
  broadphase.find_pairs(proxies, pairs);
  const ShapePair* buffer = pairs.data();
  const std::size_t capacity = pairs.capacity();
  for (BroadphaseProxy& proxy : proxies) proxy.bounds.min.y() += 0.01;
  broadphase.find_pairs(proxies, pairs);
  CHECK(pairs.size() == 99);
  CHECK(pairs.data() == buffer);
  CHECK(pairs.capacity() == capacity);
}

TEST_CASE("Boxes reaching the largest doubles are paired without overflow",
          "[FR:Determine-Collisions]") {
  // The top of the tall box is far beyond any band: its band number is clamped, not overflowed
  // (an undefined conversion the sanitizers report).
  const std::vector<BroadphaseProxy> proxies{{Aabb{{-1.0, -1e308}, {1.0, 1.7e308}}, false},
                                             {Aabb{{0.0, 0.0}, {1.0, 1.0}}, false},
                                             {Aabb{{5.0, 0.0}, {6.0, 1.0}}, false}};
  gp::SweepAndPrune broadphase(0.0);
  CHECK(as_promised(sorted(pairs_found(broadphase, proxies)), proxies, 0.0));
  CHECK(all_overlapping_pairs(proxies, 0.0) == std::vector<ShapePair>{{0, 1}});
}

TEST_CASE("A non-finite box, from a state about to be reported non-finite, is paired with none",
          "[FR:Determine-Collisions]") {
  std::vector<BroadphaseProxy> proxies{{Aabb{{0.0, 0.0}, {1.0, 1.0}}, false},
                                       {Aabb{{0.5, 0.5}, {1.5, 1.5}}, false}};
  gp::SweepAndPrune broadphase(0.0);
  REQUIRE(pairs_found(broadphase, proxies).size() == 1);
  proxies[1].bounds.max.y() = std::numeric_limits<double>::quiet_NaN();
  CHECK(pairs_found(broadphase, proxies).empty());
  proxies[1].bounds = Aabb{{0.5, -1.7e308}, {1.5, 1.0}};
  proxies[0].bounds = Aabb{{0.0, 1.7e308}, {1.0, 1.7e308}};
  // Bottoms 3.4e308 apart: their span overflows a double.
  CHECK(pairs_found(broadphase, proxies).empty());
}

TEST_CASE("Sweep and prune released finds the pairs of all-pairs testing again",
          "[FR:Determine-Collisions]") {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> position(0.0, 30.0);
  std::vector<BroadphaseProxy> proxies;
  for (int i = 0; i < 300; ++i) {
    proxies.push_back(box_proxy({position(random), position(random)}, {1.0, 1.5}, i % 7 == 0));
  }
  gp::SweepAndPrune broadphase(0.1);
  REQUIRE(as_promised(sorted(pairs_found(broadphase, proxies)), proxies, 0.1));
  broadphase.release();
  for (BroadphaseProxy& p : proxies) p.bounds = p.bounds.fattened(0.3);
  CHECK(as_promised(sorted(pairs_found(broadphase, proxies)), proxies, 0.1));
  // Placed and sorted from scratch, as nothing was kept.
  CHECK(broadphase.entries_resorted() >= proxies.size());
}

}  // namespace test_broadphase
}  // namespace
