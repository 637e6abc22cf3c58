// The bound from the bodies alone that lets solve_small_islands skip its surveys of resting
// islands, against the survey's own definitions worked by hand: a point is held unless it closes
// faster than the unheld speed, and an island is uneven where one dynamic body is more than the
// mass ratio times as heavy as another.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/solver/island_solver.hpp"

using gp::Vec2;

namespace {
namespace test_surveys_settled {

constexpr double kReach = 0.75;                    // m: contact_reach
constexpr double kUnheld = 0.1 * 9.81 / 60.0;      // m/s: 0.1 g h, as the contact solver sets it
const Vec2 kNormal = Vec2(3.0, 4.0).normalized();  // of the worst-placed point

gp::DirectSolveLimits limits() {
  return {64, 512, 10.0, 32768, 0.01, 0.035, kUnheld, 2e-4};
}

// Bodies 0 and 1 dynamic (1 kg, moment 1/6 kg·m²), body 2 static or kinematic.
struct Bodies {
  gp::BodyInertia inertia{{1.0, 1.0, 0.0}, {6.0, 6.0, 0.0}};
  gp::MotionState start;
  gp::MotionState now;

  Bodies() {
    for (gp::MotionState* s : {&start, &now}) {
      s->position.assign(3, Vec2::Zero());
      s->angle.assign(3, 0.0);
      s->velocity.assign(3, Vec2::Zero());
      s->angular_velocity.assign(3, 0.0);
    }
  }
  bool settled() const {
    return gp::surveys_settled({inertia, start, 1.0 / 60.0, {0.0, -9.81}, kReach}, now, limits());
  }
};

TEST_CASE("The surveys are skipped only where every point, however placed, is held",
          "[FR:Determine-Collision-Response-Over-Time]") {
  // The worst case of a point between bodies 0 and 1: the bodies moving into each other along
  // its normal, each at `speed`, and turning at `turning` so that its arms, crossed with the
  // normal, +kReach on A and −kReach on B, add to the approach. By hand, its normal velocity is
  // (v_A − v_B)·n + ω_A (r_A × n) − ω_B (r_B × n) = −2 (speed + turning · kReach); with a target
  // of 0 (a touching point), it is held while that is at least −kUnheld.
  Bodies bodies;
  double largest_settled = 0.0;  // of speed + turning · kReach, over the cases the bound skips
  int settled = 0;
  constexpr int kCases = 400;
  for (int k = 0; k <= kCases; ++k) {
    const double reach_speed = 2.0 * kUnheld * k / kCases;  // speed + turning · kReach
    for (const double turning_share : {0.0, 0.5, 1.0}) {
      const double turning = turning_share * reach_speed / kReach;
      const double speed = (1.0 - turning_share) * reach_speed;
      bodies.now.velocity[0] = -speed * kNormal;
      bodies.now.velocity[1] = speed * kNormal;
      bodies.now.angular_velocity[0] = -turning;
      bodies.now.angular_velocity[1] = turning;
      if (!bodies.settled()) continue;
      ++settled;
      largest_settled = std::max(largest_settled, reach_speed);
      const double normal_velocity = -2.0 * (speed + turning * kReach);
      CHECK(normal_velocity >= -kUnheld);
    }
  }
  // Not vacuous either way: it skips slow bodies and surveys fast ones.
  CHECK(settled > 0);
  CHECK(settled < 3 * (kCases + 1));
  // It skips up to a quarter of the unheld speed a body, half what the bound allows, the rest
  // left for round-off: a resting pile's bodies measured 1e-5 m/s or less after the warm start
  // (large_pyramid and many_pyramids).
  CHECK(largest_settled >= 0.24 * kUnheld);
  CHECK(largest_settled <= 0.5 * kUnheld);
}

TEST_CASE("The surveys are not skipped where a kinematic body moves, however slowly",
          "[FR:Determine-Collision-Response-Over-Time]") {
  // A kinematic body's shapes may reach farther than the bound's reach; a still one does not
  // count. Body 2 is neither dynamic nor movable (no inverse mass or moment).
  Bodies bodies;
  CHECK(bodies.settled());
  bodies.now.velocity[2] = {1e-12, 0.0};
  CHECK_FALSE(bodies.settled());
  bodies.now.velocity[2] = Vec2::Zero();
  bodies.now.angular_velocity[2] = 1e-12;
  CHECK_FALSE(bodies.settled());
}

TEST_CASE("The surveys are not skipped where one dynamic body is more than the mass ratio heavier",
          "[FR:Determine-Collision-Response-Over-Time]") {
  // An island is uneven where its lightest body's inverse mass is more than mass_ratio (10) times
  // its heaviest's: 1 kg and 10 kg are even, 1 kg and 10.1 kg not.
  Bodies bodies;
  bodies.inertia.inverse_mass[1] = 1.0 / 10.0;
  CHECK(bodies.settled());
  bodies.inertia.inverse_mass[1] = 1.0 / 10.1;
  CHECK_FALSE(bodies.settled());
}

}  // namespace test_surveys_settled
}  // namespace
