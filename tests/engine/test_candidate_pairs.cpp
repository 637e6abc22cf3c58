// Candidate pairs, kept from call to call while the boxes stay within enlarged copies
// (CandidatePairs), against testing all pairs (FR:Determine-Collisions).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include "engine/collision/candidate_pairs.hpp"
#include "engine/collision/enlarged_boxes.hpp"

using gp::ShapePair;
using gp::Vec2;

namespace {
namespace test_candidate_pairs {

constexpr double kMargin = 0.02;

// A static ground segment (body 0) under `columns` × `rows` unit boxes side by side, each row
// resting on the one below, every box its own body; each placed alike at both ends of the step.
struct Pile {
  gp::BodyShapes shapes;
  std::vector<char> dynamic;
  std::vector<Vec2> position;
  std::vector<double> angle;
  gp::WorldShapes start;
  gp::WorldBounds end;

  Pile(int columns, int rows) {
    shapes.add(0, gp::Shape::segment({-1.0, 0.0}, {columns + 1.0, 0.0}), 0.0, 0.6, false);
    dynamic.push_back(0);
    position.emplace_back(0.0, 0.0);
    angle.push_back(0.0);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        shapes.add(static_cast<gp::BodyId>(position.size()), gp::Shape::box(1.0, 1.0), 0.0, 0.6,
                   true);
        dynamic.push_back(1);
        position.emplace_back(c + 0.5, r + 0.5);
        angle.push_back(0.0);
      }
    }
  }

  const std::vector<ShapePair>& find(gp::CandidatePairs& candidates) {
    shapes.place(position, angle, start);
    shapes.place(position, angle, end);
    return candidates.find(shapes, dynamic, start, end);
  }

  // Every pair the broadphase should report, by testing all N² / 2 pairs of boxes grown by half
  // the margin, one of them dynamic.
  std::vector<ShapePair> all_pairs() {
    shapes.place(position, angle, start);
    std::vector<ShapePair> pairs;
    for (std::uint32_t i = 0; i < shapes.size(); ++i) {
      for (std::uint32_t j = i + 1; j < shapes.size(); ++j) {
        if (dynamic[shapes[i].body] == 0 && dynamic[shapes[j].body] == 0) continue;
        const gp::Aabb a = start.bounds(i).fattened(0.5 * kMargin);
        if (a.overlaps(start.bounds(j).fattened(0.5 * kMargin))) pairs.push_back({i, j});
      }
    }
    return pairs;
  }

  // Moves each box by up to `reach` [m] along x and y.
  void jostle(std::mt19937& random, double reach) {
    std::uniform_real_distribution<double> move(-reach, reach);
    for (std::size_t b = 1; b < position.size(); ++b)
      position[b] += Vec2(move(random), move(random));
  }
};

TEST_CASE("Pairs kept for a pile at rest are those of all-pairs testing at every call") {
  Pile pile(20, 10);
  gp::CandidatePairs candidates(kMargin);
  // At rest, the first two calls are calm, and the pairs are kept from the third.
  int kept_used = 0;
  for (int call = 0; call < 30; ++call) {
    REQUIRE(pile.find(candidates) == pile.all_pairs());
    kept_used += candidates.kept_pairs_used() ? 1 : 0;
  }
  CHECK(kept_used == 28);
  // Jostled by millimetres, boxes side by side come within the margin and leave it again: the
  // kept pairs are filtered down to each call's.
  std::mt19937 random(7);
  for (int call = 0; call < 30; ++call) {
    pile.jostle(random, 0.005);
    REQUIRE(pile.find(candidates) == pile.all_pairs());
    CHECK(candidates.kept_pairs_used());
  }
  // Boxes thrown onto the pile leave their enlarged boxes, whose pairs are found anew, among
  // them the pair of two thrown side by side; the boxes of the pile they left lose theirs.
  pile.position[5] = {10.3, 10.5};
  pile.position[6] = {11.3, 10.5};
  pile.position[70] = {-3.0, 0.5};
  CHECK(pile.find(candidates) == pile.all_pairs());
  CHECK(candidates.kept_pairs_used());
  CHECK(std::ranges::count(candidates.pairs(), ShapePair{5, 6}) == 1);
  CHECK(pile.find(candidates) == pile.all_pairs());
  CHECK(candidates.kept_pairs_used());
  // More boxes thrown at once than are refreshed one by one: pairs found afresh, and kept again.
  for (std::size_t b = 1; b <= gp::CandidatePairs::kRefreshedBoxes + 1; ++b)
    pile.position[b] = {-3.0 - 1.5 * static_cast<double>(b), 0.5};
  CHECK(pile.find(candidates) == pile.all_pairs());
  CHECK_FALSE(candidates.kept_pairs_used());
  CHECK(pile.find(candidates) == pile.all_pairs());
  CHECK(candidates.kept_pairs_used());
}

TEST_CASE("Boxes on the move keep no pairs, and their pairs are those of all-pairs testing") {
  Pile pile(20, 10);
  gp::CandidatePairs candidates(kMargin);
  std::mt19937 random(11);
  for (int call = 0; call < 30; ++call) {
    pile.jostle(random, 0.3);
    REQUIRE(pile.find(candidates) == pile.all_pairs());
    CHECK_FALSE(candidates.kept_pairs_used());
  }
}

TEST_CASE("Pairs kept and filtered on two threads are those of one thread") {
  // 4800 boxes: some 19,000 kept pairs, filtered in blocks on the threads.
  Pile pile(80, 60);
  std::mt19937 random(3);
  gp::CandidatePairs one(kMargin);
  gp::CandidatePairs two(kMargin);
  for (int call = 0; call < 6; ++call) {
    if (call >= 4) pile.jostle(random, 0.005);
    const std::vector<ShapePair> alone = tbb::task_arena(1).execute([&] { return pile.find(one); });
    const std::vector<ShapePair> shared =
        tbb::task_arena(2).execute([&] { return pile.find(two); });
    REQUIRE(shared == alone);
    CHECK(one.kept_pairs_used() == (call >= 2));
    CHECK(two.kept_pairs_used() == (call >= 2));
  }
  CHECK(pile.find(one) == pile.all_pairs());
}

TEST_CASE("An enlarged box of floats holds the box of doubles it was made from") {
  std::mt19937 random(13);
  std::uniform_real_distribution<double> side(-1e6, 1e6);
  for (int i = 0; i < 1000; ++i) {
    const double x = side(random);
    const double y = side(random);
    const gp::Aabb box{{x, y}, {x + 1e-7, y + 0.3}};
    const std::optional<gp::EnlargedBox> enlarged = gp::enlarged_box(box);
    REQUIRE(enlarged.has_value());
    const gp::Aabb held = enlarged->bounds();
    CHECK(held.min.x() <= box.min.x());
    CHECK(held.min.y() <= box.min.y());
    CHECK(held.max.x() >= box.max.x());
    CHECK(held.max.y() >= box.max.y());
    // Rounded outwards by at most a float's step: 2⁻²³ of the side's size, 0.125 m at 1e6 m.
    CHECK(box.min.x() - held.min.x() <= 0.125);
    CHECK(held.max.y() - box.max.y() <= 0.125);
  }
  // Beyond a float's range, or not a number: none, and the pairs are found without keeping.
  CHECK_FALSE(gp::enlarged_box({{0.0, 0.0}, {1e39, 1.0}}).has_value());
  CHECK_FALSE(gp::enlarged_box({{std::nan(""), 0.0}, {1.0, 1.0}}).has_value());
}

TEST_CASE("A box beyond a float's range leaves a pile's pairs to the broadphase") {
  Pile pile(4, 3);
  // 1e39 m: a double, but no float; the pile's other boxes stay at rest.
  pile.position[5] = {1e39, 0.5};
  gp::CandidatePairs candidates(kMargin);
  for (int call = 0; call < 10; ++call) {
    REQUIRE(pile.find(candidates) == pile.all_pairs());
    CHECK_FALSE(candidates.kept_pairs_used());
  }
}

}  // namespace test_candidate_pairs
}  // namespace
