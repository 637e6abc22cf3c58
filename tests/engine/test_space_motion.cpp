// Free motion in a Space against closed forms: projectile, spin-up under constant torque,
// time-dependent forces, forces at a point, a circular orbit; and the integrators' orders.
// Criteria of the closed-form checks: 3 to 10 times the error measured (Release), and no tighter
// than rounding, 1e-15 of the value (at least 1e-15), where the engine meets the closed form
// exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gamephysics/gamephysics.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;

namespace {
namespace test_space_motion {

constexpr double pi = std::numbers::pi;

gp::BodyDef point_mass(const Vec2& position, const Vec2& velocity, double mass = 56.2) {
  gp::BodyDef def;
  def.name = "p";
  def.position = position;
  def.velocity = velocity;
  def.mass = mass;
  return def;
}

// Largest position error of a projectile against x₀ + v₀t + ½gt² over 2 s.
double projectile_error(gp::IntegratorKind kind, double dt) {
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  settings.integrator = kind;
  gp::Space space(settings);
  const Vec2 x0{0.412, 44.2}, v0{2.51, 5.0};
  const auto id = space.add_body(point_mass(x0, v0));
  double worst = 0.0;
  while (space.time() < 2.0 - 1e-12) {
    space.step(dt);
    const double t = space.time();
    const Vec2 exact = x0 + v0 * t + 0.5 * settings.gravity * t * t;
    worst = std::max(worst, (space.state(id).position - exact).norm());
  }
  return worst;
}

TEST_CASE("Projectile: velocity Verlet and RK4 are exact under constant acceleration",
          "[FR:Calculate-Translation-Over-Time][via:IM:transMot]") {
  CHECK(projectile_error(gp::IntegratorKind::VelocityVerlet, 1.0 / 60) < 1e-12);
  CHECK(projectile_error(gp::IntegratorKind::RK4, 1.0 / 60) < 1e-12);
  // Symplectic Euler is first order: its error halves with the step.
  const double coarse = projectile_error(gp::IntegratorKind::SymplecticEuler, 1.0 / 60);
  const double fine = projectile_error(gp::IntegratorKind::SymplecticEuler, 1.0 / 120);
  CHECK(coarse > 1e-3);
  CHECK_THAT(coarse / fine, WithinAbs(2.0, 1e-11));
}

TEST_CASE("Under constant forces RK4 takes velocity Verlet's step, to the bit",
          "[FR:Calculate-Translation-Over-Time][via:IM:transMot][via:IM:rotMot]") {
  // Every RK4 stage then has the same accelerations, and its weighted slopes are exactly
  // v₀ + a h/2 and a: the step is the parabola's, with none of the four stages' rounding (nor
  // their cost: 4.8 times Verlet's on the bench's free10000 when they ran).
  const auto after = [](gp::IntegratorKind kind) {
    gp::Settings settings;
    settings.gravity = {0.0, -9.81};
    settings.integrator = kind;
    gp::Space space(settings);
    gp::BodyDef box = point_mass({0.412, 44.2}, {2.51, 5.0});
    box.torque = 3.7;
    box.shapes.push_back({gp::Shape::box(0.3, 0.7), 0.0, 0.0, 10.0});
    box.mass.reset();
    const auto id = space.add_body(box);
    for (int k = 0; k < 120; ++k) space.step(1.0 / 60);
    return space.state(id);
  };
  const gp::BodyState rk4 = after(gp::IntegratorKind::RK4);
  const gp::BodyState verlet = after(gp::IntegratorKind::VelocityVerlet);
  CHECK(rk4.position == verlet.position);
  CHECK(rk4.velocity == verlet.velocity);
  CHECK(rk4.angle == verlet.angle);
  CHECK(rk4.angular_velocity == verlet.angular_velocity);
}

TEST_CASE("Constant torque spins a box up as θ = ½αt² and ω = αt",
          "[FR:Calculate-Rotation-Over-Time][via:IM:rotMot]") {
  gp::Space space;
  gp::BodyDef box;
  box.name = "box";
  box.torque = 200.0;
  box.shapes.push_back({gp::Shape::box(2.0, 1.0), 0.0, 0.0, 10.0});
  const auto id = space.add_body(box);
  // A 2 × 1 box of density 10: m = 20 kg, I = m (w² + h²)/12 = 25/3 kg·m².
  CHECK_THAT(space.mass(id), WithinRel(20.0, 1e-15));
  CHECK_THAT(space.moment(id), WithinRel(25.0 / 3.0, 2e-15));
  const double alpha = 200.0 / (25.0 / 3.0);
  for (int k = 0; k < 90; ++k) space.step(1.0 / 60);
  const double t = space.time();
  CHECK_THAT(space.state(id).angular_velocity, WithinRel(alpha * t, 5e-15));
  CHECK_THAT(space.state(id).angle, WithinAbs(std::fmod(0.5 * alpha * t * t, 2 * pi), 2e-15));
  CHECK(space.state(id).position.norm() == 0.0);
}

TEST_CASE("A time-dependent force F(t) = m cos t gives v(t) = sin t",
          "[FR:Calculate-Translation-Over-Time][via:IM:transMot]") {
  gp::Settings settings;
  settings.integrator = gp::IntegratorKind::RK4;
  gp::Space space(settings);
  const auto id = space.add_body(point_mass(Vec2::Zero(), Vec2::Zero(), 2.0));
  space.set_force_callback(id, [](double t, gp::BodyId, const gp::BodyState&) {
    return gp::Wrench{{2.0 * std::cos(t), 0.0}, 0.0};
  });
  for (int k = 0; k < 100; ++k) space.step(0.01);
  // x(t) = 1 − cos t; RK4's error at h = 0.01 is far below 1e-9.
  CHECK_THAT(space.state(id).velocity.x(), WithinAbs(std::sin(1.0), 1e-11));
  CHECK_THAT(space.state(id).position.x(), WithinAbs(1.0 - std::cos(1.0), 2e-11));
}

TEST_CASE("A force applied off the centre of mass also turns the body", "[via:DD:torque]") {
  gp::Space space;
  gp::BodyDef rod;
  rod.name = "rod";
  rod.mass = 2.0;
  rod.moment = 0.5;
  rod.force = {3.0, 0.0};
  rod.force_point = Vec2{0.0, 1.0};  // above the centre: a push to +x turns it clockwise
  const auto id = space.add_body(rod);
  space.step(1e-3);
  // Over the first millisecond the arm barely turns: α ≈ r × F / I = (0·0 − 1·3)/0.5 = −6.
  CHECK_THAT(space.state(id).angular_velocity, WithinRel(-6.0e-3, 1e-11));
  CHECK_THAT(space.state(id).velocity.x(), WithinRel(1.5e-3, 1e-15));
}

TEST_CASE("Two bodies on a circular orbit keep radius, energy and angular momentum",
          "[via:TM:UniversalGravLaw][via:GD:accelGravity][FR:Calculate-Translation-Over-Time]") {
  // Equal masses m at distance 2r circle their common centre with v = √(G m / (4 r)) and
  // period T = 2π r / v.
  gp::Settings settings;
  settings.G = 1.0;
  settings.integrator = gp::IntegratorKind::RK4;
  gp::Space space(settings);
  const double m = 1.0, r = 1.0, v = std::sqrt(1.0 * m / (4 * r)), period = 2 * pi * r / v;
  const auto a = space.add_body(point_mass({r, 0.0}, {0.0, v}, m));
  const auto b = space.add_body(point_mass({-r, 0.0}, {0.0, -v}, m));
  const int steps = 2000;
  for (int k = 0; k < steps; ++k) space.step(period / steps);
  // After one period both are back where they started.
  CHECK((space.state(a).position - Vec2{r, 0.0}).norm() < 1e-9);
  CHECK((space.state(b).position - Vec2{-r, 0.0}).norm() < 1e-9);
  CHECK_THAT((space.state(a).position - space.state(b).position).norm(), WithinRel(2 * r, 2e-13));
}

TEST_CASE("Static bodies never move and kinematic bodies move at their velocity",
          "[FR:Simulation-Space]") {
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  gp::BodyDef wall;
  wall.name = "wall";
  wall.type = gp::BodyType::Static;
  wall.velocity = {5.0, 0.0};  // ignored: a static body has none
  wall.shapes.push_back({gp::Shape::box(1, 1)});
  gp::BodyDef lift = wall;
  lift.name = "lift";
  lift.type = gp::BodyType::Kinematic;
  lift.position = {10.0, 0.0};
  lift.velocity = {0.0, 1.0};
  lift.angular_velocity = 0.5;
  const auto w = space.add_body(wall);
  const auto k = space.add_body(lift);
  for (int i = 0; i < 60; ++i) space.step(1.0 / 60);
  CHECK(space.state(w).position == Vec2::Zero());
  CHECK(space.state(w).velocity == Vec2::Zero());
  CHECK_THAT((space.state(k).position - Vec2{10.0, 1.0}).norm(), WithinAbs(0.0, 5e-15));
  CHECK_THAT(space.state(k).angle, WithinAbs(0.5, 2e-15));
  CHECK(std::isinf(space.mass(w)));
}

TEST_CASE("The centre of mass of a body of several shapes is its reported position",
          "[via:DD:ctrOfMass][via:DD:momentOfInertia]") {
  gp::Space space;
  gp::BodyDef dumbbell;
  dumbbell.name = "dumbbell";
  dumbbell.position = {1.0, 2.0};
  // Two unit discs of densities 1 and 3 at x = 0 and x = 4: the centre is at x = 3.
  dumbbell.shapes.push_back({gp::Shape::circle(1.0, {0.0, 0.0}), 0.0, 0.0, 1.0});
  dumbbell.shapes.push_back({gp::Shape::circle(1.0, {4.0, 0.0}), 0.0, 0.0, 3.0});
  const auto id = space.add_body(dumbbell);
  CHECK_THAT((space.state(id).position - Vec2{4.0, 2.0}).norm(), WithinAbs(0.0, 1e-15));
  // I = Σ (½ m r² + m d²) = ½π + π·9 + ½·3π + 3π·1 = 14π.
  CHECK_THAT(space.moment(id), WithinRel(14.0 * pi, 1e-15));
  // A given mass scales the densities: the moment scales alike, the centre stays.
  dumbbell.mass = 8.0 * pi;
  const auto scaled = space.add_body(dumbbell);
  CHECK_THAT(space.moment(scaled), WithinRel(28.0 * pi, 1e-15));
  CHECK_THAT((space.state(scaled).position - Vec2{4.0, 2.0}).norm(), WithinAbs(0.0, 1e-15));
}

}  // namespace test_space_motion
}  // namespace
