// Degenerate starting positions: bodies exactly touching at rest, and bodies on top of each other.
// Each is sound physics, checked against a closed form or a conservation law
// (FR:Determine-Collision-Response-Over-Time): touching bodies at rest stay at rest; coincident
// bodies are pushed apart along a fixed direction, with no NaN, their momentum unchanged and no
// kinetic energy gained (penetration is removed by moving the bodies, not by giving them speed).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>

#include "gamephysics/gamephysics.hpp"
#include "gamephysics/models/dd/kinetic_energy.hpp"

using gp::Vec2;

namespace {
namespace test_degenerate_contacts {

constexpr double kDt = 1.0 / 60;
constexpr double kRadius = 0.5;

gp::BodyDef disc(const std::string& name, const Vec2& position) {
  gp::BodyDef def;
  def.name = name;
  def.position = position;
  def.shapes.push_back({gp::Shape::circle(kRadius)});
  return def;
}

gp::BodyDef square(const std::string& name, const Vec2& position) {
  gp::BodyDef def;
  def.name = name;
  def.position = position;
  def.shapes.push_back({gp::Shape::box(1.0, 1.0), 0.0, 0.5});
  return def;
}

gp::BodyDef ground() {
  gp::BodyDef def;
  def.name = "ground";
  def.type = gp::BodyType::Static;
  def.shapes.push_back({gp::Shape::segment({-10.0, 0.0}, {10.0, 0.0}), 0.0, 0.5});
  return def;
}

void run(gp::Space& space, int steps) {
  for (int k = 0; k < steps; ++k) space.step(kDt);
}

double kinetic_energy(const gp::Space& space) {
  double energy = 0.0;
  for (gp::BodyId id = 0; id < space.body_count(); ++id) {
    if (space.type(id) != gp::BodyType::Dynamic) continue;
    const auto s = space.state(id);
    energy +=
        gp::dd::kinetic_energy(space.mass(id), s.velocity, space.moment(id), s.angular_velocity);
  }
  return energy;
}

Vec2 momentum(const gp::Space& space) {
  Vec2 total = Vec2::Zero();
  for (gp::BodyId id = 0; id < space.body_count(); ++id) {
    total += space.mass(id) * space.state(id).velocity;
  }
  return total;
}

bool all_finite(const gp::Space& space) {
  for (gp::BodyId id = 0; id < space.body_count(); ++id) {
    const auto s = space.state(id);
    if (!s.position.allFinite() || !s.velocity.allFinite() || !std::isfinite(s.angle) ||
        !std::isfinite(s.angular_velocity)) {
      return false;
    }
  }
  return true;
}

TEST_CASE("Two equal discs touching at rest stay at rest",
          "[FR:Determine-Collision-Response-Over-Time]") {
  gp::Space space;
  const auto a = space.add_body(disc("a", {-kRadius, 0.0}));
  const auto b = space.add_body(disc("b", {kRadius, 0.0}));
  run(space, 600);
  // No force acts: Newton's first law keeps both where they are, exactly.
  CHECK(space.state(a).position == Vec2(-kRadius, 0.0));
  CHECK(space.state(b).position == Vec2(kRadius, 0.0));
  CHECK(space.state(a).velocity == Vec2::Zero());
  CHECK(space.state(b).velocity == Vec2::Zero());
}

TEST_CASE("A disc and a box resting exactly on the ground stay there",
          "[FR:Determine-Collision-Response-Over-Time]") {
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  space.add_body(ground());
  const auto ball = space.add_body(disc("ball", {-2.0, kRadius}));
  const auto box = space.add_body(square("box", {2.0, 0.5}));
  run(space, 600);
  // At rest on the ground the contact force balances gravity: no motion but the contact slop.
  for (const auto id : {ball, box}) {
    INFO(space.name(id));
    CHECK(std::abs(space.state(id).position.x() - (id == ball ? -2.0 : 2.0)) <= 1e-9);
    CHECK(std::abs(space.state(id).position.y() - 0.5) <= space.settings().linear_slop);
    CHECK(space.state(id).velocity.norm() <= 1e-6);
  }
}

TEST_CASE("Bodies started on top of each other are pushed apart without NaN or energy gain",
          "[FR:Determine-Collision-Response-Over-Time]") {
  // Each pair is 1 m across at the contact: two discs of radius 0.5 m, two unit squares, a unit
  // square and a disc. All start at rest with the same centre.
  using Maker = gp::BodyDef (*)(const std::string&, const Vec2&);
  const auto [make_a, make_b] =
      GENERATE(std::pair<Maker, Maker>{disc, disc}, std::pair<Maker, Maker>{square, square},
               std::pair<Maker, Maker>{square, disc});
  const Vec2 centre{1.0, 2.0};
  gp::Space space;
  const auto a = space.add_body(make_a("a", centre));
  const auto b = space.add_body(make_b("b", centre));
  const double total_mass = space.mass(a) + space.mass(b);
  double largest_energy = 0.0;
  for (int k = 0; k < 120; ++k) {
    space.step(kDt);
    REQUIRE(all_finite(space));
    largest_energy = std::max(largest_energy, kinetic_energy(space));
  }
  // They start at rest with no force on them: the overlap is removed by moving them, never by
  // giving them speed, so the kinetic energy stays 0 (to rounding) and so does the momentum.
  CHECK(largest_energy <= 1e-12);
  CHECK(momentum(space).norm() <= 1e-12);
  // The pushes are equal and opposite, weighted by inverse mass: the centre of mass stays put.
  const Vec2 pa = space.state(a).position;
  const Vec2 pb = space.state(b).position;
  CHECK(((space.mass(a) * pa + space.mass(b) * pb) / total_mass - centre).norm() <= 1e-9);
  // Apart to touching along a's own y axis (concentric shapes have no normal of their own, the
  // engine takes +y), less the contact slop that resting contacts keep.
  const double angle = space.state(a).angle;
  const Vec2 normal{-std::sin(angle), std::cos(angle)};
  CHECK(std::abs(normal.dot(pa - pb)) >= 1.0 - 2.0 * space.settings().linear_slop);
}

}  // namespace test_degenerate_contacts
}  // namespace
