// The shapes' boxes at the end of a step (BodyShapes::bound_moved), which the broadphase sweeps
// from their boxes at its start: each holds its shape placed whole at the end of its body's path,
// and is no looser than the turn of the body over the step allows (FR:Determine-Collisions).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/geometry/shape_extent.hpp"
#include "engine/impacts/impacts.hpp"

using gp::Shape;
using gp::Vec2;

namespace {
namespace test_end_bounds {

constexpr double kStep = 1.0 / 60.0;  // s

struct Bodies {
  gp::BodyShapes shapes;
  gp::MotionState start;
  gp::Accelerations accelerations;

  explicit Bodies(std::size_t count) {
    start.resize(count);
    accelerations.resize(count);
  }
};

TEST_CASE("A shape's box at the end of a step holds it there, and no more than its turn allows",
          "[FR:Determine-Collisions]") {
  const std::vector<Shape> shapes{
      Shape::box(1.0, 0.25),
      Shape::box(0.25, 0.25, {0.4, -0.3}),
      Shape::circle(0.3),
      Shape::circle(0.2, {0.5, 0.1}),
      Shape::segment({-0.6, 0.0}, {0.4, 0.2}, 0.05),
      Shape::polygon(std::vector<Vec2>{{-0.3, -0.2}, {0.6, -0.1}, {0.1, 0.5}})};
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  // Orientations kept within a turn, some just under 2π or just over 0, so that a path crosses
  // from one to the other; spins from none to a turn a step.
  const std::vector<double> near_whole_turn{0.0, 1e-9, 2 * std::numbers::pi - 1e-9};
  const std::vector<double> spins{0.0, 1e-6, 1.0, 60.0, 400.0};  // rad/s
  Bodies bodies(shapes.size());
  for (std::size_t b = 0; b < shapes.size(); ++b) {
    bodies.shapes.add(static_cast<gp::BodyId>(b), shapes[b], 0.0, 0.5, true);
  }
  int crossings = 0;
  for (int k = 0; k < 3000; ++k) {
    for (std::size_t b = 0; b < shapes.size(); ++b) {
      bodies.start.position[b] = {1e3 * unit(random), 10.0 * unit(random)};
      bodies.start.angle[b] = k % 2 == 0 ? std::numbers::pi * (1.0 + unit(random))
                                         : near_whole_turn[(k / 2 + b) % near_whole_turn.size()];
      bodies.start.velocity[b] = {20.0 * unit(random), 20.0 * unit(random)};
      bodies.start.angular_velocity[b] =
          spins[(static_cast<std::size_t>(k) + b) % spins.size()] * unit(random);
      bodies.accelerations.linear[b] = {0.0, -9.81};
      bodies.accelerations.angular[b] = 10.0 * unit(random);
    }
    for (const gp::PathShape kind : {gp::PathShape::kParabola, gp::PathShape::kEndVelocity}) {
      const gp::Ballistic path(bodies.start, gp::StepAccelerations(bodies.accelerations), kind,
                               kStep);
      gp::WorldShapes start;
      bodies.shapes.place(bodies.start.position, bodies.start.angle, start);
      gp::WorldBounds end;
      bodies.shapes.bound_moved(start, bodies.start.position, path, kStep, end);
      REQUIRE(end.size() == shapes.size());
      for (std::size_t i = 0; i < shapes.size(); ++i) {
        const gp::ShapeRecord& shape = bodies.shapes[i];
        const gp::Aabb whole = path.placed(shape, kStep).bounds;
        const gp::Aabb& bound = end.bounds(i);
        const double turn = path.turn(shape.body, kStep);
        const double angle = path.angle(shape.body, kStep);
        crossings += std::abs(angle - bodies.start.angle[shape.body]) > std::numbers::pi &&
                     std::abs(turn) < 1.0;
        CAPTURE(k, i, turn, bodies.start.angle[shape.body], angle);
        CHECK((bound.min.array() <= whole.min.array()).all());
        CHECK((bound.max.array() >= whole.max.array()).all());
        if (shape.centred_disc()) {
          // Placed exactly: it needs no sine.
          CHECK(bound.min == whole.min);
          CHECK(bound.max == whole.max);
        }
        // Each side within two moves of |turn| · reach (at most 2 reach): the box at the start
        // against the tight one, and the growth.
        const double looser = 2.0 * std::min(std::abs(turn), 2.0) * gp::core_reach(shape.local);
        CHECK(((whole.min - bound.min).array() <= looser + 1e-9).all());
        CHECK(((bound.max - whole.max).array() <= looser + 1e-9).all());
      }
    }
  }
  // Paths that cross 0 or 2π with a small turn were among them, grown for that turn alone.
  CHECK(crossings > 100);
}

}  // namespace test_end_bounds
}  // namespace
