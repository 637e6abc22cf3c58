// Impacts resolved for their own bodies inside a step (LocalImpacts): a chain of impacts within
// one step, and one running over into the next, against the closed form, an impact on a body in
// resting contact left to the solver, and no allocation in a step once a scene is warmed up.
// Criteria of the closed-form checks: 3 to 10 times the error measured (Release), and no tighter
// than rounding, 1e-15 of the value (at least 1e-15), where the engine meets the closed form
// exactly.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/space_impl.hpp"
#include "gamephysics/gamephysics.hpp"
#include "gamephysics/models/dd/kinetic_energy.hpp"
#include "gamephysics/models/dd/potential_energy.hpp"
#include "heap_counter.hpp"

using Catch::Matchers::WithinAbs;
using gp::Vec2;

namespace {
namespace test_local_impacts {

gp::BodyDef wall(const std::string& name, const Vec2& a, const Vec2& b, double restitution) {
  gp::BodyDef def;
  def.name = name;
  def.type = gp::BodyType::Static;
  def.shapes.push_back({gp::Shape::segment(a, b), restitution, 0.0, 1.0});
  return def;
}

gp::BodyDef disc(const std::string& name, const Vec2& position, const Vec2& velocity,
                 double restitution, double friction = 0.0) {
  gp::BodyDef def;
  def.name = name;
  def.position = position;
  def.velocity = velocity;
  def.shapes.push_back({gp::Shape::circle(0.1), restitution, friction, 1.0});
  return def;
}

TEST_CASE("Two impacts in one step, a disc into a corner, follow the closed-form reflections",
          "[via:IM:col2D][FR:Determine-Collision-Response-Over-Time]") {
  gp::Space space;
  space.add_body(wall("floor", {-1.0, 0.0}, {2.0, 0.0}, 1.0));
  space.add_body(wall("wall", {0.0, -1.0}, {0.0, 2.0}, 1.0));
  const auto ball = space.add_body(disc("ball", {0.5, 0.7}, {-30.0, -30.0}, 1.0));
  space.step(1.0 / 30);
  // The disc's surface meets the wall after 0.4 m (t = 1/75 s) and the floor after 0.6 m
  // (t = 1/50 s); each elastic impact reverses one component, so after the step it has moved
  // 1 m in each direction less twice its way to each surface.
  REQUIRE(space.impacts().size() == 2);
  CHECK_THAT(space.impacts()[0].time, WithinAbs(1.0 / 75, 1e-13));
  CHECK_THAT(space.impacts()[1].time, WithinAbs(1.0 / 50, 5e-14));
  const auto s = space.state(ball);
  CHECK_THAT(s.velocity.x(), WithinAbs(30.0, 5e-14));
  CHECK_THAT(s.velocity.y(), WithinAbs(30.0, 5e-14));
  CHECK_THAT(s.position.x(), WithinAbs(0.1 + 0.6, 5e-12));
  CHECK_THAT(s.position.y(), WithinAbs(0.1 + 0.4, 5e-12));
}

TEST_CASE("A row of discs passes the impulse on at the closed-form times, a step apart too",
          "[via:IM:col2D][FR:Determine-Collision-Response-Over-Time]") {
  // Four equal elastic discs in a row, 5 mm, 2 mm and 15 mm apart, the first moving at 1 m/s:
  // each impact hands the whole velocity on, at t = 5 ms, 7 ms and 22 ms. The third disc is
  // struck by the second impact, which is found only after the first, and the last gap is
  // within the contact margin (20 mm): the contact made at the start of the step, from the
  // third disc's old path, must not stand in for its impact in the next step.
  gp::Space space;
  const double h = 1.0 / 60;
  const double x_c = 0.4 + 0.005 + 0.002;
  const double x_d = x_c + 0.2 + 0.015;
  space.add_body(disc("a", {0.0, 0.0}, {1.0, 0.0}, 1.0));
  space.add_body(disc("b", {0.2 + 0.005, 0.0}, {0.0, 0.0}, 1.0));
  const auto c = space.add_body(disc("c", {x_c, 0.0}, {0.0, 0.0}, 1.0));
  const auto d = space.add_body(disc("d", {x_d, 0.0}, {0.0, 0.0}, 1.0));
  space.step(h);
  REQUIRE(space.impacts().size() == 2);
  CHECK_THAT(space.impacts()[0].time, WithinAbs(0.005, 1e-15));
  CHECK_THAT(space.impacts()[1].time, WithinAbs(0.007, 1e-15));
  CHECK_THAT(space.state(c).velocity.x(), WithinAbs(1.0, 1e-15));
  CHECK_THAT(space.state(c).position.x(), WithinAbs(x_c + (h - 0.007), 1e-15));
  CHECK_THAT(space.state(d).velocity.x(), WithinAbs(0.0, 1e-15));
  CHECK_THAT(space.state(d).position.x(), WithinAbs(x_d, 1e-15));
  space.step(h);
  REQUIRE(space.impacts().size() == 1);
  CHECK_THAT(space.impacts()[0].time, WithinAbs(0.022, 1e-15));
  CHECK_THAT(space.state(c).velocity.x(), WithinAbs(0.0, 1e-15));
  CHECK_THAT(space.state(d).velocity.x(), WithinAbs(1.0, 1e-15));
  CHECK_THAT(space.state(d).position.x(), WithinAbs(x_d + (2 * h - 0.022), 1e-15));
}

TEST_CASE("Impacts left over at the step's limit are resolved as contacts at its end",
          "[FR:Determine-Collision-Response-Over-Time][via:TM:NewtonThirdLawMot]") {
  // The row of discs with one impact a step: the first impact (5 ms) is exact, the second
  // (7 ms) is over the limit and must still be met, by the contact of the two discs at the end
  // of the step, rather than let them run 9.7 mm into each other.
  gp::Settings settings;
  settings.max_impacts_per_step = 1;
  gp::Space space(settings);
  const double h = 1.0 / 60;
  const auto a = space.add_body(disc("a", {0.0, 0.0}, {1.0, 0.0}, 1.0));
  const auto b = space.add_body(disc("b", {0.2 + 0.005, 0.0}, {0.0, 0.0}, 1.0));
  const auto c = space.add_body(disc("c", {0.4 + 0.005 + 0.002, 0.0}, {0.0, 0.0}, 1.0));
  space.step(h);
  REQUIRE(space.impacts().size() == 1);
  CHECK_THAT(space.impacts()[0].time, WithinAbs(0.005, 1e-15));
  const double gap = space.state(c).position.x() - space.state(b).position.x() - 0.2;
  CHECK(gap > -settings.linear_slop);
  // The contact stops b's approach; momentum is kept whatever it does.
  CHECK(space.state(c).velocity.x() >= space.state(b).velocity.x() - 1e-9);
  double momentum = 0.0;
  for (gp::BodyId id : {a, b, c}) momentum += space.mass(id) * space.state(id).velocity.x();
  CHECK_THAT(momentum, WithinAbs(space.mass(a) * 1.0, 1e-15));
}

TEST_CASE("A disc dropped fast on a disc resting on the floor stops on it and adds no energy",
          "[FR:Determine-Collision-Response-Over-Time][via:GD:impulse]") {
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  space.add_body(wall("floor", {-1.0, 0.0}, {1.0, 0.0}, 0.0));
  const auto below = space.add_body(disc("below", {0.0, 0.1}, {0.0, 0.0}, 0.0));
  const auto above = space.add_body(disc("above", {0.0, 0.6}, {0.0, -15.0}, 0.0));
  const auto energy = [&] {
    double e = 0.0;
    for (const auto id : {below, above}) {
      const auto s = space.state(id);
      e +=
          gp::dd::kinetic_energy(space.mass(id), s.velocity, space.moment(id), s.angular_velocity) +
          gp::dd::potential_energy(space.mass(id), settings.gravity, s.position);
    }
    return e;
  };
  const double start = energy();
  for (int k = 0; k < 120; ++k) {
    space.step(1.0 / 60);
    // 15 m/s covers 0.25 m a step, more than the 0.2 m disc: only the contact holds it.
    REQUIRE(space.state(above).position.y() - space.state(below).position.y() > 0.19);
    REQUIRE(space.state(below).position.y() > 0.09);
    REQUIRE(energy() <= start + 1e-9);
  }
  // At rest, stacked: below on the floor, above on it.
  CHECK_THAT(space.state(above).position.y(), WithinAbs(0.3, 2e-3));
  CHECK_THAT(space.state(above).velocity.y(), WithinAbs(0.0, 1e-15));
}

TEST_CASE("Two discs or two boxes stacked 1 cm above the floor land on it and rest",
          "[FR:Determine-Collision-Response-Over-Time][via:GD:impulse]") {
  // The lower body's impact on the floor is a speculative contact, as the body rests on the upper
  // one. Closing only the gap at the start left it g h²/2 = 1.36 mm above the floor for good,
  // moving at the 0.082 m/s that would close it: the bodies' free fall lags h × their end
  // velocity by that much. The reference is statics: at rest, overlapping by at most the slop.
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  const auto [shape, half] =
      GENERATE(std::pair{gp::Shape::circle(0.1), 0.1}, std::pair{gp::Shape::box(0.2, 0.2), 0.1});
  const auto body = [&shape = shape](const std::string& name, double y) {
    gp::BodyDef def;
    def.name = name;
    def.position = {0.0, y};
    def.shapes.push_back({shape, 0.0, 0.6, 1.0});
    return def;
  };
  space.add_body(wall("floor", {-1.0, 0.0}, {1.0, 0.0}, 0.0));
  const double gap = 0.01;  // m
  const auto lower = space.add_body(body("lower", half + gap));
  const auto upper = space.add_body(body("upper", 3.0 * half + gap));
  for (int k = 0; k < 60; ++k) space.step(1.0 / 60);
  const double slop = settings.linear_slop;
  // Measured: overlaps of 2.05e-4 to 2.12e-4 m, the slop; speeds of 0 (discs) and 7e-8 m/s
  // (boxes), bounded far below the 0.082 m/s the bodies kept while held above the floor.
  const double floor_gap = space.state(lower).position.y() - half;
  const double stack_gap =
      space.state(upper).position.y() - space.state(lower).position.y() - 2.0 * half;
  CHECK(floor_gap <= 0.0);
  CHECK(floor_gap >= -2.0 * slop);
  CHECK(stack_gap <= 0.0);
  CHECK(stack_gap >= -2.0 * slop);
  CHECK_THAT(space.state(lower).velocity.norm(), WithinAbs(0.0, 1e-6));
  CHECK_THAT(space.state(upper).velocity.norm(), WithinAbs(0.0, 1e-6));
}

TEST_CASE("A box landing on a speculative contact as its angle wraps does not turn",
          "[FR:Determine-Collision-Response-Over-Time][via:GD:impulse]") {
  // Two boxes stacked 1 cm above the floor, the lower turning at 1e-3 rad/s, as in the test
  // above. Its angle, kept in [0, 2π), wraps in the step it lands in: from 1.4e-9 rad just under
  // 2π when set at 0, and from just under 2π to just over 0 when set 2.5 steps' turn short of 2π.
  // Read across the wrap as a turn of 2π, it tilted the landing box by 0.0088 and 0.0065 rad.
  // The reference: landing flat, the box turns no more than its spin would turn it freely over
  // the run, 1e-3 rad/s × 0.5 s.
  constexpr double kSpin = 1e-3;  // rad/s
  constexpr double kH = 1.0 / 60;
  const double angle = GENERATE(0.0, 2.0 * std::numbers::pi - 2.5 * kH * kSpin);
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  gp::BodyDef floor = wall("floor", {-1.0, 0.0}, {1.0, 0.0}, 0.0);
  floor.shapes[0].friction = 0.6;
  space.add_body(floor);
  const auto box = [](const std::string& name, double y) {
    gp::BodyDef def;
    def.name = name;
    def.position = {0.0, y};
    def.shapes.push_back({gp::Shape::box(0.2, 0.2), 0.0, 0.6, 1.0});
    return def;
  };
  gp::BodyDef lower_def = box("lower", 0.11);
  lower_def.angle = angle;
  lower_def.angular_velocity = kSpin;
  const auto lower = space.add_body(lower_def);
  space.add_body(box("upper", 0.31));
  double largest_turn = 0.0;  // rad, from the angle it was set at
  for (int k = 0; k < 30; ++k) {
    space.step(kH);
    const double turn = std::remainder(space.state(lower).angle - angle, 2.0 * std::numbers::pi);
    largest_turn = std::max(largest_turn, std::abs(turn));
  }
  // Measured: 4.4e-5 and 7.4e-5 rad.
  CHECK(largest_turn <= kSpin * 30 * kH);
}

TEST_CASE("A disc turned back by an impact stays in the step unless it can pass a resting body",
          "[FR:Determine-Collision-Response-Over-Time][via:IM:col2D]") {
  // A disc at 24 m/s strikes the wall at x = 0 early in the step (τ = 1/480 s) and returns
  // towards a disc resting on the floor, which the contact solver moves. In the rest of the step
  // it can close 0.35 m on it, more than the 0.1 m half thickness of either.
  const double h = 1.0 / 60;
  const auto run = [h](double resting_x) {
    auto space = std::make_unique<gp::Space>();
    space->add_body(wall("wall", {0.0, -1.0}, {0.0, 2.0}, 1.0));
    space->add_body(wall("floor", {-1.0, 0.0}, {2.0, 0.0}, 0.0));
    const auto resting = space->add_body(disc("resting", {resting_x, 0.1}, {0.0, 0.0}, 1.0));
    const auto flying = space->add_body(disc("flying", {0.15, 0.15}, {-24.0, 0.0}, 1.0));
    space->step(h);
    return std::tuple{std::move(space), resting, flying};
  };
  const auto centre_gap = [](const gp::Space& space, gp::BodyId a, gp::BodyId b) {
    return (space.state(a).position - space.state(b).position).norm() - 0.2;
  };
  SECTION("0.30 m apart at the impact: it cannot pass, and the step stays one piece") {
    const auto [space, resting, flying] = run(0.6);
    CHECK(gp::SpaceInternals::runner(*space).sub_steps() == 0);
    // The closed-form reflection: back to x = 0.1 at τ, then 24 m/s for the other 7/480 s.
    CHECK_THAT(space->state(flying).velocity.x(), WithinAbs(24.0, 1e-13));
    CHECK_THAT(space->state(flying).position.x(), WithinAbs(0.45, 1e-13));
    // The overlap left to the next step's contact (4.2 cm) is less than half a disc, and that
    // contact turns the flying disc back without letting it through.
    CHECK(centre_gap(*space, resting, flying) > -0.1);
    for (int k = 0; k < 30; ++k) space->step(h);
    CHECK(space->state(flying).position.x() < space->state(resting).position.x());
  }
  SECTION("0.20 m apart at the impact: it could pass, and the step is sub-stepped") {
    const auto [space, resting, flying] = run(0.5);
    // One sub-step to the wall's impact, then the rest of the step as a local pass again, which
    // hands the approach to the resting disc to the contact solver.
    CHECK(gp::SpaceInternals::runner(*space).sub_steps() == 1);
    CHECK(gp::SpaceInternals::runner(*space).local_passes() == 2);
    // The discs end the step apart, and no energy was made: of two equal frictionless discs,
    // the squared speeds sum to at most the 24² m²/s² of the flying one.
    CHECK(centre_gap(*space, resting, flying) > -2e-4);
    CHECK(space->state(flying).position.x() < space->state(resting).position.x());
    CHECK(space->state(resting).velocity.squaredNorm() +
              space->state(flying).velocity.squaredNorm() <=
          24.0 * 24.0 * (1.0 + 1e-12));
  }
}

TEST_CASE("After each sub-step the rest of the step is tried as a local pass again",
          "[FR:Determine-Collision-Response-Over-Time][via:IM:col2D]") {
  // Two discs at 24 m/s strike walls, the first at x = 0 (τ = 1/480 s), the second at x = 1.5
  // (τ = 1/200 s); each then returns towards a disc resting on the floor, 0.2 m and 0.14 m away,
  // which it could pass within the step. Each impact stops a local pass: the first sub-step ends
  // at the first impact, the local pass tried after it stops at the second, the next sub-step ends
  // there, and the local pass tried after that finishes the step, handing both approaches to the
  // contact solver. Sub-stepping on after the first try would end sub-steps at each approach too,
  // five in all.
  gp::Space space;
  space.add_body(wall("left wall", {0.0, -1.0}, {0.0, 2.0}, 1.0));
  space.add_body(wall("right wall", {1.5, -1.0}, {1.5, 2.0}, 1.0));
  space.add_body(wall("floor", {-1.0, 0.0}, {2.5, 0.0}, 0.0));
  const auto resting_left = space.add_body(disc("resting left", {0.5, 0.1}, {0.0, 0.0}, 1.0));
  const auto resting_right = space.add_body(disc("resting right", {1.06, 0.1}, {0.0, 0.0}, 1.0));
  const auto flying_left = space.add_body(disc("flying left", {0.15, 0.15}, {-24.0, 0.0}, 1.0));
  const auto flying_right = space.add_body(disc("flying right", {1.28, 0.15}, {24.0, 0.0}, 1.0));
  space.step(1.0 / 60);
  CHECK(gp::SpaceInternals::runner(space).sub_steps() == 2);
  CHECK(gp::SpaceInternals::runner(space).local_passes() == 3);
  // Each flying disc ends the step apart from its resting one, on its side, and no energy was
  // made: of four equal frictionless discs, the squared speeds sum to at most 2 × 24² m²/s².
  const auto centre_gap = [&space](gp::BodyId a, gp::BodyId b) {
    return (space.state(a).position - space.state(b).position).norm() - 0.2;
  };
  CHECK(centre_gap(resting_left, flying_left) > -2e-4);
  CHECK(centre_gap(resting_right, flying_right) > -2e-4);
  CHECK(space.state(flying_left).position.x() < space.state(resting_left).position.x());
  CHECK(space.state(flying_right).position.x() > space.state(resting_right).position.x());
  double squared_speeds = 0.0;
  for (const auto id : {resting_left, resting_right, flying_left, flying_right}) {
    squared_speeds += space.state(id).velocity.squaredNorm();
  }
  CHECK(squared_speeds <= 2 * 24.0 * 24.0 * (1.0 + 1e-12));
}

TEST_CASE("A step allocates nothing once the scene is warmed up", "[FR:Simulation-Space]") {
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  space.add_body(wall("floor", {-2.0, 0.0}, {2.0, 0.0}, 0.0));
  space.add_body(wall("left", {-2.0, 0.0}, {-2.0, 4.0}, 0.0));
  space.add_body(wall("right", {2.0, 0.0}, {2.0, 4.0}, 0.0));
  for (int i = 0; i < 60; ++i) {
    space.add_body(disc(std::string("d") + std::to_string(i),
                        {-1.5 + 0.3 * (i % 10), 0.5 + 0.3 * (i / 10)}, {0.0, 0.0}, 0.2, 0.5));
  }
  for (int k = 0; k < 600; ++k) space.step(1.0 / 60);
  const long before = gp::test::allocations();
  for (int k = 0; k < 120; ++k) space.step(1.0 / 60);
  CHECK(gp::test::allocations() - before == 0);
  // The count is real: a vector's growth shows in it.
  std::vector<double> grown(1000);
  CHECK(gp::test::allocations() > before);
}

}  // namespace test_local_impacts
}  // namespace
