// Sleeping (Settings::sleep): an island at rest is held still, and wakes when a body reaches it,
// an edit or a force is applied to it, or a kinematic body moves into it. Checked against closed
// forms and conservation of momentum.
#include <catch2/catch.hpp>
#include <string>

#include "engine/geometry/world_bounds.hpp"
#include "engine/sleep/sleeping.hpp"
#include "engine/space_impl.hpp"
#include "gamephysics/gamephysics.hpp"

using Catch::Matchers::WithinAbs;
using gp::Vec2;

namespace {
namespace test_sleeping {

constexpr double g = 9.81;      // m/s²
constexpr double kStep = 0.01;  // s

gp::Settings sleepy(double gravity = g) {
  gp::Settings settings;
  settings.gravity = {0.0, -gravity};
  settings.sleep = true;
  return settings;
}

gp::BodyDef ground() {
  gp::BodyDef def;
  def.name = "ground";
  def.type = gp::BodyType::Static;
  def.shapes.push_back({gp::Shape::segment({-20.0, 0.0}, {20.0, 0.0}), 0.0, 0.0});
  return def;
}

// A unit box of 1 kg resting on the ground, frictionless.
gp::BodyDef resting_box(const std::string& name, double x) {
  gp::BodyDef def;
  def.name = name;
  def.position = {x, 0.5};
  def.shapes.push_back({gp::Shape::box(1.0, 1.0), 0.0, 0.0});
  return def;
}

bool asleep(const gp::Space& space, gp::BodyId body) {
  return gp::asleep(gp::SpaceInternals::context(space), body);
}

void run(gp::Space& space, double seconds) {
  for (int k = 0; k < static_cast<int>(seconds / kStep + 0.5); ++k) space.step(kStep);
}

// Adds the ground and a box resting on it, and runs `space` until the box has slept for about half
// a second; the box.
gp::BodyId box_asleep(gp::Space& space) {
  space.add_body(ground());
  const auto box = space.add_body(resting_box("box", 0.0));
  run(space, 1.0);
  REQUIRE(asleep(space, box));
  return box;
}

TEST_CASE("A box at rest falls asleep after time_to_sleep and is then held exactly still",
          "[FR:Simulation-Space]") {
  gp::Space space(sleepy());
  space.add_body(ground());
  const auto box = space.add_body(resting_box("box", 0.0));
  run(space, 0.4);
  CHECK_FALSE(asleep(space, box));
  run(space, 0.2);  // 0.6 s > time_to_sleep = 0.5 s
  REQUIRE(asleep(space, box));
  const gp::BodyState held = space.state(box);
  run(space, 1.0);
  CHECK(space.state(box).position == held.position);
  CHECK(space.state(box).angle == held.angle);
  CHECK(space.state(box).velocity == Vec2::Zero());
  // Resting within the slop of where it was put: sleeping moved it by nothing more.
  CHECK_THAT(held.position.y(), WithinAbs(0.5, 3e-4));
  // The stages are listed, and the sleeping ones run.
  bool listed = false;
  for (const gp::PipelineStage& s : space.pipeline())
    listed = listed || (s.needed && s.name == "sleep: islands at rest fall asleep");
  CHECK(listed);
}

TEST_CASE("Without sleep, nothing sleeps and the sleep stages are not needed",
          "[FR:Simulation-Space]") {
  gp::Settings settings = sleepy();
  settings.sleep = false;
  gp::Space space(settings);
  space.add_body(ground());
  const auto box = space.add_body(resting_box("box", 0.0));
  run(space, 2.0);
  CHECK_FALSE(asleep(space, box));
  for (const gp::PipelineStage& s : space.pipeline()) {
    if (s.name.rfind("sleep", 0) == 0) CHECK_FALSE(s.needed);
  }
}

TEST_CASE("An impulse wakes a sleeping body, which then moves by J/m (DD:impulseV)",
          "[FR:Simulation-Space][via:DD:impulseV]") {
  gp::Space space(sleepy());
  const auto box = box_asleep(space);
  const double x0 = space.state(box).position.x();
  space.apply_impulse(box, {2.0, 0.0}, space.state(box).position);
  CHECK_FALSE(asleep(space, box));
  run(space, 0.1);
  // Frictionless ground: 2 N·s on 1 kg slides it at 2 m/s, 0.2 m in 0.1 s.
  CHECK_THAT(space.state(box).velocity.x(), WithinAbs(2.0, 1e-9));
  CHECK_THAT(space.state(box).position.x() - x0, WithinAbs(0.2, 1e-9));
}

TEST_CASE("A sliding box that reaches a sleeping one wakes it, and momentum is conserved",
          "[FR:Determine-Collisions][via:TM:NewtonThirdLawMot]") {
  gp::Space space(sleepy());
  space.add_body(ground());
  const auto still = space.add_body(resting_box("still", 0.0));
  run(space, 1.0);
  REQUIRE(asleep(space, still));
  gp::BodyDef slider = resting_box("slider", -3.0);
  slider.velocity = {1.0, 0.0};
  const auto moving = space.add_body(slider);
  run(space, 3.0);
  CHECK_FALSE(asleep(space, still));
  // Equal masses, C_R = 0, no friction: they move on together at half the speed.
  const double p = space.state(still).velocity.x() + space.state(moving).velocity.x();
  CHECK_THAT(p, WithinAbs(1.0, 1e-9));
  CHECK(space.state(still).velocity.x() > 0.4);
}

// Whether the box of the box's shape as the step placed it (world_start, at the start of the last
// step) is the one of the shape placed afresh where the box was then.
bool placed_where_it_was(const gp::Space& space, gp::BodyId box, const gp::BodyState& before) {
  const gp::StepContext& c = gp::SpaceInternals::context(space);
  const auto [shape, last] = c.shapes.of_body(box);
  const gp::Aabb kept = c.world_start.bounds(shape);
  const gp::Aabb fresh =
      gp::placed_bounds(c.shapes[shape].local, gp::Transform(before.position, before.angle));
  return kept.min == fresh.min && kept.max == fresh.max;
}

TEST_CASE("A sleeping body's shapes are not placed again, and are once it moves",
          "[FR:Determine-Collisions]") {
  gp::Space space(sleepy());
  const auto box = box_asleep(space);
  // Asleep for half a second: the shape kept where the box fell asleep is where it still is.
  gp::BodyState before = space.state(box);
  space.step(kStep);
  CHECK(placed_where_it_was(space, box, before));
  CHECK(gp::placed_asleep(gp::SpaceInternals::context(space), box));
  // Woken by an impulse, it slides away; each step places it where that step started.
  space.apply_impulse(box, {2.0, 0.0}, space.state(box).position);
  CHECK_FALSE(gp::placed_asleep(gp::SpaceInternals::context(space), box));
  for (int k = 0; k < 5; ++k) {
    before = space.state(box);
    space.step(kStep);
    CHECK(placed_where_it_was(space, box, before));
  }
  CHECK(space.state(box).position.x() > before.position.x());
}

TEST_CASE("A space whose every body sleeps stands still: its steps advance the clock alone",
          "[FR:Simulation-Space]") {
  gp::Space space(sleepy());
  space.add_body(ground());
  const auto left = space.add_body(resting_box("left", -2.0));
  const auto right = space.add_body(resting_box("right", 2.0));
  const gp::StepRunner& runner = gp::SpaceInternals::runner(space);
  run(space, 0.6);
  REQUIRE(asleep(space, left));
  REQUIRE(asleep(space, right));
  const gp::BodyState held = space.state(right);
  // Asleep since about 0.5 s: the step after they fell asleep emptied the contacts.
  const std::uint64_t passes = runner.local_passes() + runner.sub_steps();
  const std::uint64_t still = runner.still_steps();
  CHECK(still > 0);
  const double t0 = space.time();
  for (int k = 0; k < 50; ++k) space.step(kStep);
  CHECK(runner.still_steps() == still + 50);
  CHECK(runner.local_passes() + runner.sub_steps() == passes);
  CHECK_THAT(space.time() - t0, WithinAbs(50 * kStep, 1e-12));
  CHECK(space.state(right).position == held.position);
  // Standing still, the space holds no room for contacts.
  CHECK(gp::SpaceInternals::context(space).contacts.empty());
  // An impulse wakes one island; the other sleeps on, and the space moves again.
  space.apply_impulse(left, {2.0, 0.0}, space.state(left).position);
  space.step(kStep);
  CHECK(runner.still_steps() == still + 50);
  CHECK_THAT(space.state(left).velocity.x(), WithinAbs(2.0, 1e-9));
  CHECK(asleep(space, right));
  // It slides into the other, whose contact is found afresh: equal masses, C_R = 0, no friction,
  // they move on together at half its speed.
  run(space, 3.0);
  CHECK_FALSE(asleep(space, right));
  const double p = space.state(left).velocity.x() + space.state(right).velocity.x();
  CHECK_THAT(p, WithinAbs(2.0, 1e-9));
  CHECK(space.state(right).velocity.x() > 0.9);
}

TEST_CASE("A kinematic body moving into a sleeping island wakes it", "[FR:Simulation-Space]") {
  gp::Space space(sleepy());
  const auto box = box_asleep(space);
  gp::BodyDef paddle;
  paddle.name = "paddle";
  paddle.type = gp::BodyType::Kinematic;
  paddle.position = {-2.0, 0.5};
  paddle.velocity = {2.0, 0.0};
  paddle.shapes.push_back({gp::Shape::box(0.5, 0.5), 0.0, 0.0});
  space.add_body(paddle);
  run(space, 1.0);
  CHECK_FALSE(asleep(space, box));
  // Pushed ahead of the paddle, which does not yield: at least its speed.
  CHECK(space.state(box).velocity.x() >= 2.0 - 1e-9);
}

}  // namespace test_sleeping
}  // namespace
