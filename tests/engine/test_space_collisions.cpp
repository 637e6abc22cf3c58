// Collisions in a Space against closed forms and conservation laws: head-on and oblique impacts,
// an off-centre impact that sets a box spinning, bounce times and heights, a stack that must stay
// put, and a bullet that must not pass through a thin wall.
// Criteria of the closed-form checks: 3 to 10 times the error measured (Release), and no tighter
// than rounding, 1e-15 of the value (at least 1e-15), where the engine meets the closed form
// exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "box_pyramid.hpp"
#include "gamephysics/gamephysics.hpp"
#include "gamephysics/models/dd/kinetic_energy.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;

namespace {
namespace test_space_collisions {
gp::BodyDef disc(const std::string& name, const Vec2& position, const Vec2& velocity,
                 double restitution, double radius = 0.5, double density = 1.0) {
  gp::BodyDef def;
  def.name = name;
  def.position = position;
  def.velocity = velocity;
  def.shapes.push_back({gp::Shape::circle(radius), restitution, 0.0, density});
  return def;
}

struct Totals {
  Vec2 momentum = Vec2::Zero();
  double angular_momentum = 0.0;  // about the origin
  double energy = 0.0;            // kinetic, with rotation
};

Totals totals(const gp::Space& space) {
  Totals t;
  for (gp::BodyId id = 0; id < space.body_count(); ++id) {
    if (space.type(id) != gp::BodyType::Dynamic) continue;
    const auto s = space.state(id);
    const double m = space.mass(id);
    const double I = std::isinf(space.moment(id)) ? 0.0 : space.moment(id);
    t.momentum += m * s.velocity;
    t.angular_momentum += m * gp::cross(s.position, s.velocity) + I * s.angular_velocity;
    t.energy += gp::dd::kinetic_energy(m, s.velocity, I, s.angular_velocity);
  }
  return t;
}

TEST_CASE("Head-on collisions: equal masses exchange velocities, C_R scales the rebound",
          "[FR:Determine-Collision-Response-Over-Time][via:IM:col2D]") {
  const double cr = GENERATE(1.0, 0.5);
  gp::Space space;
  const auto a = space.add_body(disc("a", {-2.0, 0.0}, {2.51, 0.0}, cr));
  const auto b = space.add_body(disc("b", {2.0, 0.0}, {-1.0, 0.0}, cr));
  for (int k = 0; k < 120; ++k) space.step(1.0 / 60);
  // 1D closed form for equal masses: v_a' = (v_a + v_b − C_R (v_a − v_b)) / 2, and for b alike.
  const double va = 2.51, vb = -1.0;
  CHECK_THAT(space.state(a).velocity.x(), WithinAbs((va + vb - cr * (va - vb)) / 2, 2e-15));
  CHECK_THAT(space.state(b).velocity.x(), WithinAbs((va + vb + cr * (va - vb)) / 2, 5e-15));
  // They touch when the 3 m gap closes at 3.51 m/s.
  REQUIRE(space.time() > 3.0 / 3.51);
}

TEST_CASE("The impact is found at its exact time inside the step", "[via:IM:col2D]") {
  gp::Space space;
  space.add_body(disc("a", {-2.0, 0.0}, {2.51, 0.0}, 1.0));
  space.add_body(disc("b", {2.0, 0.0}, {-1.0, 0.0}, 1.0));
  std::vector<gp::Impact> impacts;
  for (int k = 0; k < 120; ++k) {
    space.step(1.0 / 60);
    impacts.insert(impacts.end(), space.impacts().begin(), space.impacts().end());
  }
  REQUIRE(impacts.size() == 1);
  CHECK_THAT(impacts[0].time, WithinRel(3.0 / 3.51, 1e-14));
  // j = (1 + C_R) μ v_closing with μ = m/2, m = π·0.5² kg.
  CHECK_THAT(impacts[0].impulse, WithinRel(2.0 * (0.25 * std::numbers::pi / 2) * 3.51, 1e-15));
}

TEST_CASE("Oblique elastic collision of discs conserves momentum and energy",
          "[FR:Determine-Collision-Response-Over-Time][via:IM:col2D][via:DD:kEnergy]") {
  gp::Space space;
  const auto a = space.add_body(disc("a", {-3.0, 0.3}, {2.51, 0.0}, 1.0));
  const auto b = space.add_body(disc("b", {0.0, 0.0}, {0.0, 0.0}, 1.0));
  const Totals before = totals(space);
  for (int k = 0; k < 120; ++k) space.step(1.0 / 60);
  const Totals after = totals(space);
  CHECK_THAT((after.momentum - before.momentum).norm(), WithinAbs(0.0, 1e-15));
  CHECK_THAT(after.energy, WithinRel(before.energy, 1e-15));
  // Equal masses, one at rest, elastic: they leave at right angles, b along the line of centres
  // at the moment of contact (offset 0.3 over a distance 1: sin θ = 0.3).
  const Vec2 va = space.state(a).velocity, vb = space.state(b).velocity;
  CHECK_THAT(va.dot(vb), WithinAbs(0.0, 1e-15));
  CHECK_THAT(vb.normalized().y(), WithinAbs(-0.3, 1e-15));
}

TEST_CASE("An off-centre impact sets a box spinning and conserves angular momentum",
          "[FR:Determine-Collision-Response-Over-Time][via:IM:col2D][via:DD:torque]") {
  gp::Space space;
  gp::BodyDef box;
  box.name = "box";
  box.shapes.push_back({gp::Shape::box(2.0, 1.0), 1.0, 0.0, 1.0});
  const auto b = space.add_body(box);
  const auto ball = space.add_body(disc("ball", {-3.0, 0.4}, {5.0, 0.0}, 1.0, 0.2, 5.0));
  const Totals before = totals(space);
  for (int k = 0; k < 60; ++k) space.step(1.0 / 60);
  const Totals after = totals(space);
  CHECK(std::abs(space.state(b).angular_velocity) > 0.1);  // hit above the centre: it turns
  CHECK(space.state(b).angular_velocity < 0.0);            // clockwise
  CHECK_THAT((after.momentum - before.momentum).norm(), WithinAbs(0.0, 1e-15));
  CHECK_THAT(after.angular_momentum, WithinAbs(before.angular_momentum, 2e-15));
  CHECK_THAT(after.energy, WithinRel(before.energy, 1e-15));
  CHECK(space.state(ball).velocity.x() < 5.0);
}

TEST_CASE("Bouncing ball at dt = 1/60 s keeps its closed-form bounce times and heights",
          "[FR:Determine-Collision-Response-Over-Time][via:IM:col2D][via:DD:coeffRestitution]") {
  const double g = 9.81, h0 = 10.0, cr = 0.8, r = 0.5;
  gp::Settings settings;
  settings.gravity = {0.0, -g};
  gp::Space space(settings);
  gp::BodyDef ground;
  ground.name = "ground";
  ground.type = gp::BodyType::Static;
  ground.shapes.push_back({gp::Shape::segment({-10, 0}, {10, 0}), cr});
  space.add_body(ground);
  const auto ball = space.add_body(disc("ball", {0.0, h0 + r}, Vec2::Zero(), cr, r));
  // Bounce k starts at t_k with speed C_R^k v₁ and rises to h_k = C_R^(2k) h₀.
  const double v1 = std::sqrt(2 * g * h0);
  const auto height = [&](double t) {
    double start = std::sqrt(2 * h0 / g), speed = cr * v1;
    if (t < start) return h0 - 0.5 * g * t * t;
    while (t >= start + 2 * speed / g) start += 2 * speed / g, speed *= cr;
    return speed * (t - start) - 0.5 * g * (t - start) * (t - start);
  };
  std::vector<double> bounce_times;
  double worst = 0.0;
  for (int k = 0; k < 600; ++k) {
    space.step(1.0 / 60);
    for (const auto& i : space.impacts()) bounce_times.push_back(i.time);
    worst = std::max(worst, std::abs(space.state(ball).position.y() - r - height(space.time())));
  }
  CHECK(worst < 1e-9);
  REQUIRE(bounce_times.size() >= 3);
  double expected = std::sqrt(2 * h0 / g), speed = cr * v1;
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK_THAT(bounce_times[k], WithinAbs(expected, 5e-14));
    expected += 2 * speed / g;
    speed *= cr;
  }
}

TEST_CASE("A 1 cm disc at 500 m/s never crosses a 1 cm wall", "[FR:Determine-Collisions]") {
  const double dt = GENERATE(1.0 / 60, 1.0 / 240);
  gp::Space space;
  gp::BodyDef wall;
  wall.name = "wall";
  wall.type = gp::BodyType::Static;
  wall.position = {1.0, 0.0};
  wall.shapes.push_back({gp::Shape::box(0.01, 1.0)});
  space.add_body(wall);
  const auto bullet = space.add_body(disc("bullet", {0.0, 0.1}, {500.0, 0.0}, 0.0, 0.005));
  for (int k = 0; k < 30; ++k) {
    space.step(dt);
    CHECK(space.state(bullet).position.x() < 1.0 - 0.005 - 0.005 + 1e-6);
  }
}

TEST_CASE("A 20-row pyramid of boxes stays put for 10 s",
          "[FR:Determine-Collision-Response-Over-Time]") {
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  const std::vector<gp::BodyId> boxes = gp::test::add_box_pyramid(space, 20, 1.0);
  std::vector<Vec2> start;
  for (gp::BodyId b : boxes) start.push_back(space.state(b).position);
  for (int k = 0; k < 600; ++k) space.step(1.0 / 60);
  double worst = 0.0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    worst = std::max(worst, (space.state(boxes[i]).position - start[i]).norm());
  }
  CHECK(worst < 0.01);
}

TEST_CASE("Collisions conserve linear momentum in a closed box of discs",
          "[FR:Determine-Collision-Response-Over-Time][via:TM:NewtonThirdLawMot]") {
  gp::Space space;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      // The letter inserted, not "d" + …, which GCC 12 flags falsely (-Wstringop-overflow).
      space.add_body(disc(std::to_string(6 * i + j).insert(0, 1, 'd'), {1.5 * i, 1.5 * j + 0.1 * i},
                          {std::sin(7.0 * i + j), std::cos(3.0 * j - i)}, 0.7));
    }
  }
  const Totals before = totals(space);
  for (int k = 0; k < 300; ++k) space.step(1.0 / 60);
  CHECK_THAT((totals(space).momentum - before.momentum).norm(), WithinAbs(0.0, 5e-15));
  CHECK(totals(space).energy <= before.energy * (1 + 1e-12));  // C_R < 1 loses, never gains
}

TEST_CASE("A Newton's cradle of touching balls passes the momentum to its last ball",
          "[via:IM:col2D][via:TM:NewtonThirdLawMot]") {
  gp::Space space;
  std::vector<gp::BodyId> balls;
  // Touching elastic discs of radius 0.5 m; the first moves into the others at 2 m/s.
  balls.push_back(space.add_body(disc("ball0", {-1.0, 0.0}, {2.0, 0.0}, 1.0)));
  for (int i = 1; i < 5; ++i) {
    balls.push_back(
        space.add_body(disc("ball" + std::to_string(i), {i - 1.0, 0.0}, {0.0, 0.0}, 1.0)));
  }
  space.step(1.0 / 60);
  // The sequential model of simultaneous impacts: each pair exchanges its velocities in turn.
  for (int i = 0; i < 4; ++i) CHECK(space.state(balls[i]).velocity.norm() < 1e-12);
  CHECK_THAT(space.state(balls[4]).velocity.x(), WithinAbs(2.0, 2e-15));
  CHECK_THAT(space.state(balls[4]).position.x(), WithinAbs(3.0 + 2.0 / 60, 5e-15));
}

}  // namespace test_space_collisions
}  // namespace
