// The bound from the bodies alone that lets the position passes be skipped, against overlaps
// worked by hand: a unit box resting on the ground, moved down or turned about its centre since
// its contact was found, overlaps the ground by its lowest corner's drop.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "engine/solver/position_passes.hpp"

using gp::Vec2;

namespace {
namespace test_surely_within_slop {

constexpr double kSlop = 2e-4;     // m: Settings::linear_slop
constexpr double kMargin = 0.02;   // m: Settings::contact_margin
constexpr double kTouching = 0.0;  // m: the deepest overlap at detection, none

// Body 0 the static ground (its top at y = 0), body 1 a unit box resting on it, centred at
// (0, 0.5), found at angle `detected_angle` [rad].
struct RestingBox {
  gp::BodyShapes shapes;
  gp::BodyInertia inertia{{0.0, 1.0}, {0.0, 6.0}};
  gp::MotionState detected;
  gp::MotionState now;

  explicit RestingBox(double detected_angle = 0.0) {
    shapes.add(0, gp::Shape::box(20.0, 1.0, {0.0, -0.5}), 0.0, 0.6, false);
    shapes.add(1, gp::Shape::box(1.0, 1.0), 0.0, 0.6, true);
    for (gp::MotionState* s : {&detected, &now}) {
      s->position = {Vec2::Zero(), Vec2(0.0, 0.5)};
      s->angle = {0.0, detected_angle};
      s->velocity.assign(2, Vec2::Zero());
      s->angular_velocity.assign(2, 0.0);
    }
  }
  bool within(double deepest = kTouching) const {
    return gp::surely_within_slop(deepest, kMargin, {shapes, inertia, detected}, {4, kSlop}, now);
  }
};

// Of a unit box turned by `turn` [rad] about its centre: how far its lowest corner drops [m].
double corner_drop(double turn) {
  return 0.5 * (std::cos(turn) + std::abs(std::sin(turn)) - 1.0);
}

TEST_CASE("The position passes are skipped only where no point can overlap past the slop",
          "[FR:Determine-Collision-Response-Over-Time]") {
  RestingBox box;
  CHECK(box.within());
  SECTION("moved down") {
    double largest = 0.0;  // of the drops skipped
    for (int k = 0; k <= 400; ++k) {
      const double drop = 2.0 * kSlop * k / 400;
      box.now.position[1] = Vec2(0.0, 0.5 - drop);
      if (!box.within()) continue;
      largest = std::max(largest, drop);
      CHECK(drop <= kSlop);
    }
    // Half the slop is left to round-off, and a move is counted for both bodies of a point:
    // skipped up to a quarter of the slop.
    CHECK(largest >= 0.24 * kSlop);
    CHECK(largest <= 0.26 * kSlop);
  }
  SECTION("turned") {
    double largest = 0.0;  // of the turns skipped
    for (int k = 0; k <= 400; ++k) {
      const double turn = 4.0 * kSlop * k / 400;
      box.now.angle[1] = turn;
      if (!box.within()) continue;
      largest = std::max(largest, turn);
      CHECK(corner_drop(turn) <= kSlop);
    }
    // A turn moves a point by at most the turn times its arm, counted as the box's reach (0.71 m)
    // and the margin, for both bodies: skipped up to 1e-4 / (2 · 0.727) = 6.9e-5 rad, whose
    // corner drops 3.4e-5 m.
    CHECK(largest >= 6.5e-5);
    CHECK(largest <= 7e-5);
  }
  SECTION("already overlapping at detection") {
    // The slop leaves a point found 0.19 mm deep 0.01 mm: a move of a micrometre fits, of
    // 0.02 mm does not.
    box.now.position[1] = Vec2(0.0, 0.5 - 1e-6);
    CHECK(box.within(0.19e-3));
    box.now.position[1] = Vec2(0.0, 0.5 - 2e-5);
    CHECK_FALSE(box.within(0.19e-3));
    CHECK_FALSE(box.within(kSlop));
  }
}

TEST_CASE("A box rocking across angle 0 turns by its angle's change within half a turn",
          "[FR:Determine-Collision-Response-Over-Time]") {
  // Angles are kept in [0, 2π): found just under 2π and now just over 0, the box turned by 2e-9
  // rad, not by a whole turn less that.
  RestingBox box(2.0 * std::numbers::pi - 1e-9);
  box.now.angle[1] = 1e-9;
  CHECK(box.within());
  // A real turn of a tenth of a radian drops a corner by 4.7 cm.
  box.now.angle[1] = 0.1 - 1e-9;
  CHECK(corner_drop(0.1) > kSlop);
  CHECK_FALSE(box.within());
}

TEST_CASE("The position passes are not skipped where a disc lies off its body's centre of mass",
          "[FR:Determine-Collision-Response-Over-Time]") {
  // The passes follow such a disc's deepest point by its centre's turn and its radius along the
  // normal, which the bound does not cover.
  RestingBox box;
  box.shapes.add(1, gp::Shape::circle(0.1, {0.3, 0.0}), 0.0, 0.6, true);
  CHECK_FALSE(box.within());
}

}  // namespace test_surely_within_slop
}  // namespace
