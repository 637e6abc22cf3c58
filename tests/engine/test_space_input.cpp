// Bad input through the API (FR:Verify-Physical_Constraints): each SRS data constraint and each
// degenerate shape gives an InputError naming the body's field, the rule and the value; a run that
// produces a non-finite state stops with an error naming the body and the time.
// Criteria of the closed-form checks: 3 to 10 times the error measured (Release), and no tighter
// than rounding, 1e-15 of the value (at least 1e-15), where the engine meets the closed form
// exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "gamephysics/gamephysics.hpp"

namespace {
namespace test_space_input {
gp::BodyDef ball() {
  gp::BodyDef def;
  def.name = "ball";
  def.shapes.push_back({gp::Shape::circle(0.5)});
  return def;
}

// The InputError that adding `def` as the second body raises.
gp::InputError error_of(const gp::BodyDef& def) {
  gp::Space space;
  space.add_body(ball());
  try {
    space.add_body(def);
  } catch (const gp::InputError& e) {
    return e;
  }
  FAIL("no InputError");
  throw;
}

TEST_CASE("Each SRS data constraint on a body is checked with field, rule and value",
          "[FR:Verify-Physical_Constraints]") {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  auto def = ball();
  def.mass = -1.0;
  CHECK(std::string(error_of(def).what()) ==
        "bodies[1].mass: must be > 0 (SRS data constraint m > 0), got -1");
  def = ball();
  def.moment = 0.0;
  CHECK(error_of(def).field() == "bodies[1].moment");
  def = ball();
  def.shapes[0].restitution = 1.5;
  CHECK(error_of(def).field() == "bodies[1].shapes[0].restitution");
  CHECK(error_of(def).rule() == "must be in [0, 1] (SRS data constraint on C_R)");
  CHECK(error_of(def).value() == "1.5");
  def = ball();
  def.shapes[0].friction = -0.1;
  CHECK(error_of(def).field() == "bodies[1].shapes[0].friction");
  def = ball();
  def.shapes[0].density = 0.0;
  CHECK(error_of(def).field() == "bodies[1].shapes[0].density");
  def = ball();
  def.angle = 7.0;
  CHECK(error_of(def).rule() == "must be in [0, 2π] (SRS software constraint on ϕ)");
  def = ball();
  def.velocity = {nan, 0.0};
  CHECK(error_of(def).field() == "bodies[1].velocity");
  CHECK(error_of(def).rule() == "must be finite numbers");
  def = ball();
  def.torque = std::numeric_limits<double>::infinity();
  CHECK(error_of(def).field() == "bodies[1].torque");
  def = ball();
  def.force_point = gp::Vec2{nan, nan};
  CHECK(error_of(def).field() == "bodies[1].force_point");
  for (gp::Vec2 gp::BodyDef::*field : {&gp::BodyDef::position, &gp::BodyDef::force}) {
    def = ball();
    def.*field = {0.0, nan};
    CHECK_THAT(error_of(def).what(), Catch::Contains("must be finite numbers"));
  }
  def = ball();
  def.angular_velocity = nan;
  CHECK(error_of(def).field() == "bodies[1].angular_velocity");
}

TEST_CASE("A dynamic body needs a mass, and a moment to rotate",
          "[FR:Verify-Physical_Constraints]") {
  gp::BodyDef point;
  point.name = "point";
  CHECK(error_of(point).field() == "bodies[1].mass");
  point.mass = 1.0;
  point.angular_velocity = 1.0;
  CHECK(error_of(point).field() == "bodies[1].moment");
  gp::BodyDef line = point;
  line.angular_velocity = 0.0;
  line.mass.reset();
  line.shapes.push_back({gp::Shape::segment({0, 0}, {1, 0}, 0.0)});
  CHECK(error_of(line).field() == "bodies[1].mass");  // a bare line has no area, so no mass
}

TEST_CASE("Degenerate shapes are refused by the shape factories",
          "[FR:Verify-Physical_Constraints]") {
  CHECK_THROWS_AS(gp::Shape::circle(0.0), std::invalid_argument);
  CHECK_THROWS_AS(gp::Shape::box(1.0, -1.0), std::invalid_argument);
  const std::vector<gp::Vec2> collinear{{0, 0}, {1, 0}, {2, 0}};
  CHECK_THROWS_AS(gp::Shape::polygon(collinear), std::invalid_argument);
  CHECK_THROWS_AS(gp::Shape::segment({1, 1}, {1, 1}), std::invalid_argument);
}

TEST_CASE("Settings and steps are checked too", "[FR:Verify-Physical_Constraints]") {
  gp::Settings settings;
  settings.G = -1.0;
  CHECK_THROWS_WITH(gp::Space(settings), "G: must be >= 0, got -1");
  settings = {};
  settings.gravity = {0.0, std::numeric_limits<double>::infinity()};
  CHECK_THROWS_AS(gp::Space(settings), gp::InputError);
  settings = {};
  settings.velocity_iterations = -1;
  CHECK_THROWS_AS(gp::Space(settings), gp::InputError);
  settings = {};
  settings.position_iterations = -2;
  CHECK_THROWS_AS(gp::Space(settings), gp::InputError);
  settings = {};
  settings.velocity_tolerance = std::nan("");
  CHECK_THROWS_WITH(gp::Space(settings), "velocity_tolerance: must be a finite number, got nan");
  settings = {};
  settings.linear_slop = -1e-3;
  CHECK_THROWS_WITH(gp::Space(settings), "linear_slop: must be >= 0, got -0.001");
  settings = {};
  settings.contact_margin = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(gp::Space(settings), gp::InputError);
  settings = {};
  settings.max_impacts_per_step = -1;
  CHECK_THROWS_WITH(gp::Space(settings), "max_impacts_per_step: must be >= 0, got -1");
  gp::Space space;
  CHECK_THROWS_WITH(space.step(0.0), "dt: must be > 0 (a time step), got 0");
  CHECK_THROWS_AS(space.step(std::nan("")), gp::InputError);
}

TEST_CASE("A non-finite state stops the run with the body's name and the time",
          "[FR:Verify-Physical_Constraints]") {
  gp::Space space;
  const auto id = space.add_body(ball());
  space.set_force_callback(id, [](double t, gp::BodyId, const gp::BodyState&) {
    return gp::Wrench{{t > 0.055 ? std::nan("") : 0.0, 0.0}, 0.0};
  });
  try {
    for (int k = 0; k < 10; ++k) space.step(0.01);
    FAIL("no NumericalError");
  } catch (const gp::NumericalError& e) {
    CHECK(e.body() == "ball");
    // Velocity Verlet evaluates the force at both ends of a step: first NaN at the end of
    // [0.05, 0.06].
    CHECK_THAT(e.time(), Catch::Matchers::WithinAbs(0.06, 1e-15));
    CHECK_THAT(e.what(), Catch::Contains("body 'ball' has a non-finite state"));
  }
}

TEST_CASE("Orientations are reported in 0 ≤ ϕ < 2π",
          "[via:DD:angDisp][FR:Calculate-Rotation-Over-Time]") {
  gp::Space space;
  auto def = ball();
  def.angle = 2.0 * std::numbers::pi;  // allowed as input, the same orientation as 0
  def.angular_velocity = -3.0;
  const auto id = space.add_body(def);
  CHECK(space.state(id).angle == 0.0);
  for (int k = 0; k < 100; ++k) {
    space.step(0.05);
    CHECK(space.state(id).angle >= 0.0);
    CHECK(space.state(id).angle < 2.0 * std::numbers::pi);
  }
}

}  // namespace test_space_input
}  // namespace
