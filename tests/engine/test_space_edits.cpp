// Changing a space between steps against closed forms: a set state then free flight, impulses
// (DD:impulseV, DD:torque), a force for one step, removal (the body no longer collides, the others
// run exactly as if it had never been there) and finding bodies by name; and each change checked
// like the scene file.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "gamephysics/gamephysics.hpp"

using Catch::Matchers::WithinAbs;
using gp::Vec2;

namespace {
namespace test_space_edits {

constexpr double g = 9.81;  // m/s²

gp::Settings falling() {
  gp::Settings settings;
  settings.gravity = {0.0, -g};
  return settings;
}

gp::BodyDef ground(const std::string& name = "ground") {
  gp::BodyDef def;
  def.name = name;
  def.type = gp::BodyType::Static;
  def.shapes.push_back({gp::Shape::segment({-20.0, 0.0}, {20.0, 0.0})});
  return def;
}

// A disc of mass 2 kg and moment 0.5 kg·m² (given, not from its area).
gp::BodyDef disc(const std::string& name, const Vec2& position, double radius = 0.5) {
  gp::BodyDef def;
  def.name = name;
  def.position = position;
  def.mass = 2.0;
  def.moment = 0.5;
  def.shapes.push_back({gp::Shape::circle(radius)});
  return def;
}

gp::BodyDef box(const std::string& name, const Vec2& position) {
  gp::BodyDef def;
  def.name = name;
  def.position = position;
  def.shapes.push_back({gp::Shape::box(1.0, 1.0), 0.0, 0.5});
  return def;
}

// A point mass of 1 kg at the origin, without a moment of inertia.
gp::BodyDef point_mass() {
  gp::BodyDef def;
  def.name = "point";
  def.mass = 1.0;
  return def;
}

// The message of the InputError that `change` throws; empty if none.
template <typename Change>
std::string error_of(Change change) {
  try {
    change();
  } catch (const gp::InputError& e) {
    return e.what();
  }
  return "";
}

TEST_CASE("A set position and velocity, then free flight, follow the parabola",
          "[FR:Calculate-Translation-Over-Time][via:IM:transMot]") {
  gp::Space space(falling());
  const auto id = space.add_body(disc("ball", {0.0, 50.0}));
  for (int k = 0; k < 10; ++k) space.step(0.01);
  const double t0 = space.time();
  space.set_position(id, {1.0, 20.0});
  space.set_velocity(id, {3.0, 4.0});
  for (int k = 0; k < 100; ++k) space.step(0.01);
  const double t = space.time() - t0;
  // x = 1 + 3t, y = 20 + 4t − ½gt², exact for velocity Verlet under constant acceleration.
  CHECK_THAT(space.state(id).position.x(), WithinAbs(1.0 + 3.0 * t, 1e-12));
  CHECK_THAT(space.state(id).position.y(), WithinAbs(20.0 + 4.0 * t - 0.5 * g * t * t, 1e-12));
  CHECK_THAT(space.state(id).velocity.y(), WithinAbs(4.0 - g * t, 1e-12));
}

TEST_CASE("A set angle and angular velocity turn a free body as ϕ = ϕ₀ + ωt, mod 2π",
          "[FR:Calculate-Rotation-Over-Time][via:DD:angDisp]") {
  gp::Space space;
  const auto id = space.add_body(disc("wheel", {0.0, 0.0}));
  space.set_angle(id, 7.0);
  CHECK_THAT(space.state(id).angle, WithinAbs(7.0 - 2.0 * std::numbers::pi, 1e-15));
  space.set_angular_velocity(id, 3.0);
  for (int k = 0; k < 50; ++k) space.step(0.01);
  // 7 + 3 · 0.5 = 8.5 rad, less one turn.
  CHECK_THAT(space.state(id).angle, WithinAbs(8.5 - 2.0 * std::numbers::pi, 1e-12));
  CHECK(space.state(id).angular_velocity == 3.0);
}

TEST_CASE("An impulse changes v by J/m and ω by (r × J)/I", "[via:DD:impulseV][via:DD:torque]") {
  gp::Space space;
  const auto id = space.add_body(disc("puck", {1.0, 2.0}));
  space.set_velocity(id, {0.5, 0.0});
  // At the centre of mass: Δv = (3, −1) / 2 kg, no turn.
  space.apply_impulse(id, {3.0, -1.0}, {1.0, 2.0});
  CHECK(space.state(id).velocity == Vec2(2.0, -0.5));
  CHECK(space.state(id).angular_velocity == 0.0);
  // 0.3 m above the centre, J = (4, 0): Δv = (2, 0); r × J = 0 · 0 − 0.3 · 4 = −1.2 N·m·s, and
  // Δω = −1.2 / 0.5 = −2.4 rad/s (clockwise: pushed right above its centre).
  space.apply_impulse(id, {4.0, 0.0}, {1.0, 2.3});
  CHECK_THAT(space.state(id).velocity.x(), WithinAbs(4.0, 1e-15));
  CHECK_THAT(space.state(id).angular_velocity, WithinAbs(-2.4, 1e-14));
}

TEST_CASE("A force acts for the next step only, with its torque about the centre of mass",
          "[via:IM:transMot][via:IM:rotMot][via:DD:torque]") {
  gp::Space space;
  const auto id = space.add_body(disc("puck", {0.0, 0.0}));
  // F = (10, 0) N, 0.2 m below the centre: a = 5 m/s², τ = −(−0.2) · 10 = 2 N·m, α = 4 rad/s².
  space.apply_force(id, {10.0, 0.0}, {0.0, -0.2});
  const double h = 0.1;
  space.step(h);
  CHECK_THAT(space.state(id).velocity.x(), WithinAbs(5.0 * h, 1e-15));
  CHECK_THAT(space.state(id).position.x(), WithinAbs(0.5 * 5.0 * h * h, 1e-15));
  CHECK_THAT(space.state(id).angular_velocity, WithinAbs(4.0 * h, 1e-15));
  // Then free: constant velocities.
  space.step(h);
  CHECK_THAT(space.state(id).velocity.x(), WithinAbs(5.0 * h, 1e-15));
  CHECK_THAT(space.state(id).position.x(), WithinAbs(0.5 * 5.0 * h * h + 5.0 * h * h, 1e-15));
  CHECK_THAT(space.state(id).angular_velocity, WithinAbs(4.0 * h, 1e-15));
}

TEST_CASE("Forces applied before one step add up, to a body with forces of its own",
          "[via:IM:transMot]") {
  gp::Space space(falling());
  auto def = disc("rocket", {0.0, 0.0});
  def.force = {0.0, 30.0};  // N, constant
  const auto id = space.add_body(def);
  space.apply_force(id, {4.0, 0.0}, {0.0, 0.0});
  space.apply_force(id, {2.0, 0.0}, {0.0, 0.0});
  space.step(0.5);
  // a = ((6, 30) N) / 2 kg + (0, −9.81) = (3, 5.19) m/s² for 0.5 s.
  CHECK_THAT(space.state(id).velocity.x(), WithinAbs(1.5, 1e-14));
  CHECK_THAT(space.state(id).velocity.y(), WithinAbs((15.0 - g) * 0.5, 1e-14));
  space.step(0.5);
  CHECK_THAT(space.state(id).velocity.x(), WithinAbs(1.5, 1e-14));
  CHECK_THAT(space.state(id).velocity.y(), WithinAbs((15.0 - g) * 1.0, 1e-14));
}

TEST_CASE("What is added between a force for one step and the step outlasts the step",
          "[via:IM:transMot]") {
  gp::Space space;
  const auto a = space.add_body(disc("a", {0.0, 0.0}));
  space.apply_force(a, {2.0, 0.0}, {0.0, 0.0});
  // Added, and given a callback, while a's force for one step is pending.
  auto def = disc("b", {5.0, 0.0});
  def.force = {0.0, 4.0};  // N, constant: 2 m/s² on 2 kg
  const auto b = space.add_body(def);
  space.set_force_callback(a, [](double, gp::BodyId, const gp::BodyState&) {
    return gp::Wrench{{0.0, -2.0}, 0.0};  // N: −1 m/s²
  });
  space.step(0.5);
  space.step(0.5);
  // a: 1 m/s² along x for the first 0.5 s only; −1 m/s² along y throughout. b: 2 m/s² along y.
  CHECK_THAT(space.state(a).velocity.x(), WithinAbs(0.5, 1e-14));
  CHECK_THAT(space.state(a).velocity.y(), WithinAbs(-1.0, 1e-14));
  CHECK_THAT(space.state(b).velocity.y(), WithinAbs(2.0, 1e-14));
}

TEST_CASE("A removed body no longer collides: what rested on it falls freely",
          "[FR:Determine-Collisions]") {
  gp::Space space(falling());
  space.add_body(ground());
  const auto block = space.add_body(box("block", {0.0, 0.5}));
  const auto ball = space.add_body(disc("ball", {0.0, 1.5}));
  for (int k = 0; k < 120; ++k) space.step(1.0 / 60);
  // Resting on the block, with contacts and warm starts.
  REQUIRE(space.state(ball).position.y() > 1.45);
  REQUIRE(space.state(ball).velocity.norm() < 1e-3);
  const double y0 = space.state(ball).position.y();
  const double v0 = space.state(ball).velocity.y();
  space.remove_body(block);
  CHECK(space.removed(block));
  CHECK_FALSE(space.find_body("block"));
  for (const gp::ContactPointReport& p : space.contact_points()) {
    CHECK(p.body_a != block);
    CHECK(p.body_b != block);
  }
  // Free fall for 0.3 s (to y0 − 0.44 m, above the ground at 0.5 m), with nothing left to push it.
  for (int k = 0; k < 18; ++k) space.step(1.0 / 60);
  const double t = 18.0 / 60;
  CHECK_THAT(space.state(ball).position.y(), WithinAbs(y0 + v0 * t - 0.5 * g * t * t, 1e-12));
  // Then it lands on the ground, where the block was.
  for (int k = 0; k < 120; ++k) space.step(1.0 / 60);
  CHECK_THAT(space.state(ball).position.y(), WithinAbs(0.5, 1e-2));
  CHECK(space.find_body("ball") == ball);
}

TEST_CASE("Removing a body that touches nothing leaves the others' run exactly as it was",
          "[FR:Determine-Collisions]") {
  // Two spaces of a block with a ball on it, and a kinematic body far away, touching nothing,
  // whose shape comes before theirs: removed from one space after a second, the others' shape
  // indices and warm starts move down, and the run goes on to the bit as in the other space.
  const auto build = [](gp::Space& space) {
    space.add_body(ground());
    auto far = box("far", {15.0, 5.0});
    far.type = gp::BodyType::Kinematic;
    space.add_body(far);
    space.add_body(box("block", {0.0, 0.5}));
    space.add_body(disc("ball", {0.3, 1.6}));
  };
  gp::Space kept(falling()), removed(falling());
  build(kept);
  build(removed);
  for (int k = 0; k < 60; ++k) {
    kept.step(1.0 / 60);
    removed.step(1.0 / 60);
  }
  removed.remove_body(1);
  for (int k = 0; k < 120; ++k) {
    kept.step(1.0 / 60);
    removed.step(1.0 / 60);
  }
  for (gp::BodyId j : {gp::BodyId{2}, gp::BodyId{3}}) {
    CHECK(kept.state(j).position == removed.state(j).position);
    CHECK(kept.state(j).angle == removed.state(j).angle);
    CHECK(kept.state(j).velocity == removed.state(j).velocity);
  }
  CHECK(removed.find_body("ball") == gp::BodyId{3});
  CHECK(kept.contact_points().size() == removed.contact_points().size());
}

TEST_CASE("Removing the only moving body stops all collision work", "[FR:Determine-Collisions]") {
  gp::Space space(falling());
  space.add_body(ground());
  const auto ball = space.add_body(disc("ball", {0.0, 0.5}));
  const auto point = space.add_body(point_mass());
  space.step(0.01);
  REQUIRE_FALSE(space.contact_points().empty());
  space.remove_body(ball);
  CHECK(space.contact_points().empty());
  space.step(0.5);
  // The point mass falls on: ½ g t² over 0.51 s.
  CHECK_THAT(space.state(point).position.y(), WithinAbs(-0.5 * g * 0.51 * 0.51, 1e-12));
}

TEST_CASE("Each change is checked like the scene file, and a refused one changes nothing",
          "[FR:Verify-Physical_Constraints]") {
  gp::Space space;
  space.add_body(ground());
  const auto ball = space.add_body(disc("ball", {0.0, 1.0}));
  const auto point = space.add_body(point_mass());
  const double nan = std::nan("");
  CHECK(error_of([&] {
          space.set_velocity(ball, {nan, 0.0});
        }) == "bodies[1].velocity: must be finite numbers, got [nan, 0]");
  CHECK(error_of([&] {
          space.set_position(ball, {0.0, INFINITY});
        }) == "bodies[1].position: must be finite numbers, got [0, inf]");
  CHECK(error_of([&] { space.set_angle(ball, nan); }) ==
        "bodies[1].angle: must be a finite number, got nan");
  CHECK(error_of([&] {
          space.set_velocity(0, {1.0, 0.0});
        }) == "bodies[0].velocity: cannot be set on a static body, which never moves, got static");
  CHECK(error_of([&] { space.set_angular_velocity(0, 1.0); }) ==
        "bodies[0].angular_velocity: cannot be set on a static body, which never moves, got "
        "static");
  CHECK(error_of([&] { space.set_angular_velocity(point, 1.0); }) ==
        "bodies[2].moment: is required for a body without area that rotates, got none");
  CHECK(error_of([&] {
          space.apply_impulse(0, {1.0, 0.0}, {0.0, 0.0});
        }) == "bodies[0].type: must be dynamic to take an impulse, got static");
  CHECK(error_of([&] {
          space.apply_impulse(ball, {1.0, 0.0}, {nan, 0.0});
        }) == "bodies[1].point: must be finite numbers, got [nan, 0]");
  CHECK(error_of([&] {
          space.apply_force(0, {1.0, 0.0}, {0.0, 0.0});
        }) == "bodies[0].type: must be dynamic to take a force, got static");
  CHECK(error_of([&] {
          space.apply_force(ball, {INFINITY, 0.0}, {0.0, 0.0});
        }) == "bodies[1].force: must be finite numbers, got [inf, 0]");
  CHECK(error_of([&] {
          space.set_velocity(7, {1.0, 0.0});
        }) == "bodies[7]: must be a body of the space, got no such body (3 bodies)");
  // Nothing changed: the ball is where it was, at rest.
  CHECK(space.state(ball).position == Vec2(0.0, 1.0));
  CHECK(space.state(ball).velocity == Vec2::Zero());
  CHECK(space.state(point).angular_velocity == 0.0);
  space.set_angular_velocity(point, 0.0);  // 0 needs no moment
  space.remove_body(ball);
  CHECK(error_of([&] { space.remove_body(ball); }) ==
        "bodies[1]: must be a body of the space, got a removed body");
  CHECK(error_of([&] {
          space.set_position(ball, {0.0, 0.0});
        }) == "bodies[1]: must be a body of the space, got a removed body");
}

TEST_CASE("Bodies are found by name, the first added when names repeat", "[FR:Simulation-Space]") {
  gp::Space space;
  const auto a = space.add_body(disc("a", {0.0, 0.0}));
  const auto b = space.add_body(disc("b", {5.0, 0.0}));
  const auto b2 = space.add_body(disc("b", {10.0, 0.0}));
  CHECK(space.find_body("a") == a);
  CHECK(space.find_body("b") == b);
  CHECK_FALSE(space.find_body("c"));
  space.remove_body(b);
  CHECK(space.find_body("b") == b2);
}

}  // namespace test_space_edits
}  // namespace
