// A pair's first touch within a step (find_touch, touch_time), against closed forms: a disc
// falling onto a floor is apart at the step's start and overlaps at its end, so that its touch is
// only bracketed until its time is asked for; a disc passing another within the step, apart at
// both ends, has its touch found by the search at once. Criteria: the root search's 50 bits
// (about 6e-18 s here; 4.3e-18 s measured) and the search's 1e-12 m (1.9e-14 s at the closing
// speed; 8.6e-15 s measured).
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/collision/body_shapes.hpp"
#include "engine/impacts/impacts.hpp"

using Catch::Matchers::WithinAbs;
using gp::Shape;

namespace {
namespace test_touch_search {

constexpr double kStep = 1.0 / 60.0;                   // s
constexpr gp::ImpactFilter kFilter{2e-4, 0.05, 0.02};  // the default settings'
const gp::StepWindow kWholeStep{0.0, kStep};

// Two bodies, 0 dynamic and 1 static, at rest and unaccelerated until a test sets them.
struct TwoBodies {
  gp::BodyShapes shapes;
  gp::MotionState start;
  gp::Accelerations accelerations;

  TwoBodies(const Shape& moving, const Shape& fixed) {
    shapes.add(0, moving, 0.0, 0.0, true);
    shapes.add(1, fixed, 0.0, 0.0, false);
    start.resize(2);
    accelerations.resize(2);
  }
  std::optional<gp::Touch> touch(const gp::Ballistic& motion) const {
    const gp::WorldShape a = motion.placed(shapes[0], 0.0);
    const gp::WorldShape b = motion.placed(shapes[1], 0.0);
    return gp::find_touch({shapes[0], a}, {shapes[1], b}, motion, kWholeStep, kFilter);
  }
};

TEST_CASE("A disc falling onto a floor is bracketed, its time found when asked, at the closed form",
          "[via:IM:col2D][FR:Determine-Collision-Response-Over-Time]") {
  TwoBodies bodies(Shape::circle(0.5), Shape::segment({-5.0, 0.0}, {5.0, 0.0}));
  constexpr double kGap = 0.01;    // m, the disc's lowest point above the floor
  constexpr double kSpeed = 3.0;   // m/s, down
  constexpr double kGravity = 10;  // m/s², down
  bodies.start.position[0] = {0.0, 0.5 + kGap};
  bodies.start.velocity[0] = {0.0, -kSpeed};
  bodies.accelerations.linear[0] = {0.0, -kGravity};
  const gp::Ballistic motion(bodies.start, gp::StepAccelerations(bodies.accelerations),
                             gp::PathShape::kParabola, kStep);
  const auto touch = bodies.touch(motion);
  REQUIRE(touch);
  // The gap closes as kGap − v t − g t²/2: still open at the start, closed at the step's end.
  CHECK_FALSE(touch->searched());
  CHECK_THAT(touch->distance_t0, WithinAbs(kGap, 1e-15));
  CHECK_THAT(touch->distance_h,
             WithinAbs(kGap - kSpeed * kStep - 0.5 * kGravity * kStep * kStep, 1e-15));
  // Its root, by the stable form of the quadratic's smaller root.
  const double closed_form = 2 * kGap / (kSpeed + std::sqrt(kSpeed * kSpeed + 2 * kGravity * kGap));
  const double time =
      gp::touch_time(*touch, bodies.shapes[0], bodies.shapes[1], motion, kWholeStep);
  CHECK_THAT(time, WithinAbs(closed_form, 4e-17));
  CHECK(time == gp::impact_time({bodies.shapes[0], motion.placed(bodies.shapes[0], 0.0)},
                                {bodies.shapes[1], motion.placed(bodies.shapes[1], 0.0)}, motion,
                                kWholeStep, kFilter));
}

TEST_CASE("A disc passing another within the step, apart at both ends, is found by the search",
          "[via:IM:col2D][FR:Determine-Collision-Response-Over-Time]") {
  // Disc A (r = 0.1 m) crosses the static disc B (r = 0.1 m) at 60 m/s, 0.1 m off its centre,
  // from 0.5 m before it to 0.5 m past it: it would pass through B within the step.
  TwoBodies bodies(Shape::circle(0.1), Shape::circle(0.1));
  constexpr double kSpeed = 60.0;  // m/s
  constexpr double kOffset = 0.1;  // m
  bodies.start.position[0] = {-0.5, kOffset};
  bodies.start.velocity[0] = {kSpeed, 0.0};
  const gp::Ballistic motion(bodies.start, gp::StepAccelerations(bodies.accelerations),
                             gp::PathShape::kParabola, kStep);
  const auto touch = bodies.touch(motion);
  REQUIRE(touch);
  CHECK(touch->searched());
  CHECK_THAT(touch->distance_t0, WithinAbs(std::hypot(0.5, kOffset) - 0.2, 1e-15));
  // The centres are 0.2 m apart where x² + offset² = 0.2².
  const double closed_form = (0.5 - std::sqrt(0.2 * 0.2 - kOffset * kOffset)) / kSpeed;
  // The search stops within 1e-12 m of touching, closing at 52 m/s along the normal here.
  CHECK_THAT(touch->time, WithinAbs(closed_form, 2e-14));
  CHECK(gp::touch_time(*touch, bodies.shapes[0], bodies.shapes[1], motion, kWholeStep) ==
        touch->time);

  // Passing 0.25 m off B's centre, it misses it.
  bodies.start.position[0] = {-0.5, 0.25};
  CHECK_FALSE(bodies.touch(gp::Ballistic(bodies.start, gp::StepAccelerations(bodies.accelerations),
                                         gp::PathShape::kParabola, kStep)));
}

}  // namespace test_touch_search
}  // namespace
