// The separating-axis search of two boxes (max_separation, which takes two edges at a time in the
// lanes of a 128-bit register, or four in a 256-bit one where the CPU has AVX2, and
// box_separations, both boxes' edges in one call) against its
// definition worked out one edge and one corner at a time: the same edge and the same separation
// to the bit, by every path this machine can take, over boxes placed at random and boxes lying
// exactly on each other, where separations tie.

#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <random>
#include <variant>

#include "engine/collision/hull.hpp"
#include "engine/geometry/world_shape.hpp"

namespace {
namespace test_hull {

// max over the edges i of `reference` of min over the corners v of `other` of nᵢ·(v − vᵢ), the
// first such edge on a tie, from the corners one after the other.
gp::EdgeSeparation by_definition(const gp::Hull& reference, const gp::Hull& other) {
  gp::EdgeSeparation best{0, -std::numeric_limits<double>::infinity()};
  for (int i = 0; i < reference.count(); ++i) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const gp::Vec2& v : other.vertices) {
      smallest = std::min(smallest, reference.normals[i].dot(v - reference.vertices[i]));
    }
    if (smallest > best.separation) best = {i, smallest};
  }
  return best;
}

gp::WorldShape box(double width, double height, const gp::Vec2& position, double angle) {
  return gp::to_world(gp::Shape::box(width, height), gp::Transform(position, angle));
}

void check_same(const gp::WorldShape& a, const gp::WorldShape& b) {
  const auto polygon_a = std::get<gp::PolygonView>(gp::view_of(a.geometry));
  const auto polygon_b = std::get<gp::PolygonView>(gp::view_of(b.geometry));
  const gp::Hull hull_a = gp::hull_of(polygon_a);
  const gp::Hull hull_b = gp::hull_of(polygon_b);
  const auto same = [](const gp::EdgeSeparation& found, const gp::EdgeSeparation& expected) {
    REQUIRE(found.edge == expected.edge);
    REQUIRE(std::bit_cast<std::uint64_t>(found.separation) ==
            std::bit_cast<std::uint64_t>(expected.separation));
  };
  const gp::EdgeSeparation expected = by_definition(hull_a, hull_b);
  const auto check = [&](const gp::EdgeSeparation& found) { same(found, expected); };
  const gp::BoxSeparations both_ways =
      gp::box_separations(gp::box_hull_of(polygon_a), gp::box_hull_of(polygon_b));
  same(both_ways.a, expected);
  same(both_ways.b, by_definition(hull_b, hull_a));
  check(gp::max_separation(hull_a, hull_b));
  for (const gp::Lanes lanes : {gp::Lanes::kOne, gp::Lanes::kTwo, gp::Lanes::kFour}) {
    if (lanes > gp::widest_lanes()) continue;
    INFO("a box's edges taken " << gp::box_lanes_name(lanes));
    check(gp::max_separation_of_boxes(hull_a.vertices.first<4>(), hull_a.normals.first<4>(),
                                      hull_b.vertices.first<4>(), lanes));
  }
}

TEST_CASE("This machine's box separation takes four edges at once where the CPU has AVX2",
          "[FR:Determine-Collisions]") {
#if defined(__x86_64__)
  __builtin_cpu_init();
  const bool avx2 = __builtin_cpu_supports("avx2") != 0;
#else
  const bool avx2 = false;
#endif
  CHECK((gp::widest_lanes() == gp::Lanes::kFour) == avx2);
}

TEST_CASE("Two boxes' separation, edges one, two or four at a time, is its definition to the bit",
          "[FR:Determine-Collisions]") {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> size(0.1, 3.0);
  std::uniform_real_distribution<double> place(-2.0, 2.0);
  std::uniform_real_distribution<double> turn(0.0, 6.283185307179586);
  for (int trial = 0; trial < 20000; ++trial) {
    INFO("trial " << trial);
    check_same(box(size(random), size(random), {place(random), place(random)}, turn(random)),
               box(size(random), size(random), {place(random), place(random)}, turn(random)));
  }
  // Unit boxes side by side, stacked and on one another: separations of 0 and -1 tie across
  // edges, and the first of the tied edges is the one found.
  for (const gp::Vec2& offset : {gp::Vec2(1.0, 0.0), gp::Vec2(0.0, 1.0), gp::Vec2(0.0, 0.0),
                                 gp::Vec2(0.5, 1.0), gp::Vec2(-1.0, -1.0)}) {
    check_same(box(1.0, 1.0, {0.0, 0.0}, 0.0), box(1.0, 1.0, offset, 0.0));
    check_same(box(1.0, 1.0, offset, 0.0), box(1.0, 1.0, {0.0, 0.0}, 0.0));
  }
  // A box whose place is not a number or not finite (a step about to report it): every path
  // takes the minimum as the scalar loop does, keeping the separation where a term is NaN.
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const gp::Vec2& odd : {gp::Vec2(kNaN, 0.0), gp::Vec2(kInf, 0.0), gp::Vec2(0.0, -kInf)}) {
    check_same(box(1.0, 1.0, odd, 0.0), box(1.0, 1.0, {0.0, 0.0}, 0.0));
    check_same(box(1.0, 1.0, {0.0, 0.0}, 0.0), box(1.0, 1.0, odd, 0.3));
  }
}

}  // namespace test_hull
}  // namespace
