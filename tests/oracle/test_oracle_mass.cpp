// The oracle's mass properties (verification/oracle/model) against closed forms, a quadrature of
// the capsule, and the engine's (src/engine/geometry/mass_properties, src/engine/setup/mass_setup)
// on random bodies of several shapes, written apart from them.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "engine/setup/mass_setup.hpp"
#include "random_shapes.hpp"
#include "verification/oracle/model/body_mass.hpp"
#include "verification/oracle/model/shape_integrals.hpp"

using Catch::Detail::Approx;
using gp::BodyDef;
using gp::Shape;
using gp::ShapeDef;
using gp::Vec2;

namespace {
namespace test_oracle_mass {

constexpr double kPi = std::numbers::pi;

BodyDef body_of(std::vector<ShapeDef> shapes) {
  BodyDef def;
  def.name = std::string("b");  // not `= "b"`, on which gcc 12 warns falsely (-Wstringop-overflow)
  def.shapes = std::move(shapes);
  return def;
}

/// ∫∫ (x² + y²) dA over a capsule of core length L along x, centred at the origin, by Simpson's
/// rule: the rectangle |x| ≤ L/2 in closed form per column, each end cap through x = L/2 + r sin φ,
/// whose half-height r cos φ keeps the integrand smooth.
double capsule_polar_by_quadrature(double length, double r) {
  // A column of half-height h at x: ∫ from −h to h of (x² + y²) dy = 2h x² + 2h³/3.
  const auto column = [](double x, double h) { return 2.0 * h * x * x + 2.0 * h * h * h / 3.0; };
  const auto simpson = [](auto f, double low, double high, int n) {
    const double step = (high - low) / n;
    double sum = f(low) + f(high);
    for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * f(low + i * step);
    return sum * step / 3.0;
  };
  const double half = 0.5 * length;
  const double rectangle = simpson([&](double x) { return column(x, r); }, -half, half, 2000);
  const double cap = simpson(
      [&](double phi) {
        return column(half + r * std::sin(phi), r * std::cos(phi)) * r * std::cos(phi);
      },
      0.0, 0.5 * kPi, 2000);
  return rectangle + 2.0 * cap;
}

TEST_CASE("Oracle mass: closed forms of a box, a disc, a capsule and a bare segment",
          "[oracle][mass]") {
  SECTION("a box w × h of mass m: I = m (w² + h²) / 12, about its centre wherever it is") {
    BodyDef def = body_of({{Shape::box(3.0, 0.5, Vec2(2.0, -1.0))}});
    def.mass = 6.0;
    const gp::oracle::BodyMass m = gp::oracle::body_mass(def);
    CHECK(m.mass == 6.0);
    CHECK(m.center.x() == Approx(2.0).margin(1e-15));
    CHECK(m.center.y() == Approx(-1.0).margin(1e-15));
    CHECK(m.moment == Approx(6.0 * (9.0 + 0.25) / 12.0).epsilon(1e-14));
  }
  SECTION("a disc of radius r and density ρ: m = ρ π r², I = m r² / 2") {
    const gp::oracle::BodyMass m =
        gp::oracle::body_mass(body_of({{Shape::circle(0.5, Vec2(1.0, 1.0)), 0.0, 0.0, 4.0}}));
    CHECK(m.mass == Approx(4.0 * kPi * 0.25).epsilon(1e-15));
    CHECK(m.moment == Approx(0.5 * m.mass * 0.25).epsilon(1e-15));
    CHECK((m.center - Vec2(1.0, 1.0)).norm() == 0.0);
  }
  SECTION("a capsule: area 2rL + π r², polar moment by a quadrature of its outline") {
    const double length = 1.7;
    const double r = 0.3;
    const gp::oracle::ShapeIntegrals s =
        gp::oracle::capsule_integrals(Vec2(-0.85, 0.0), Vec2(0.85, 0.0), r);
    CHECK(s.area == Approx(2.0 * r * length + kPi * r * r).epsilon(1e-15));
    // Measured 4.8e-15 relative (Simpson's error with 2000 intervals and round-off).
    CHECK(s.polar_moment == Approx(capsule_polar_by_quadrature(length, r)).epsilon(5e-14));
  }
  SECTION("two discs side by side: the parallel-axis theorem, I = 2 (m r²/2 + m d²)") {
    const gp::oracle::BodyMass m = gp::oracle::body_mass(
        body_of({{Shape::circle(0.5, Vec2(-1.0, 0.0))}, {Shape::circle(0.5, Vec2(1.0, 0.0))}}));
    const double disc = kPi * 0.25;
    CHECK(m.mass == Approx(2.0 * disc).epsilon(1e-15));
    CHECK(m.center.norm() == 0.0);
    CHECK(m.moment == Approx(2.0 * (0.5 * disc * 0.25 + disc * 1.0)).epsilon(1e-15));
  }
  SECTION("a bare segment weighs nothing; a point mass sits at its origin with the given moment") {
    BodyDef def = body_of({{Shape::segment(Vec2(0.0, 0.0), Vec2(4.0, 0.0))}});
    def.mass = 2.0;
    def.moment = 3.0;
    const gp::oracle::BodyMass m = gp::oracle::body_mass(def);
    CHECK(m.mass == 2.0);
    CHECK(m.moment == 3.0);
    CHECK(m.center.norm() == 0.0);
    const gp::oracle::BodyMass line = gp::oracle::body_mass(
        body_of({{Shape::segment(Vec2(0.0, 0.0), Vec2(4.0, 0.0))}, {Shape::box(1.0, 1.0)}}));
    CHECK(line.mass == Approx(1.0).epsilon(1e-15));
    CHECK(line.center.norm() == Approx(0.0).margin(1e-16));
  }
}

TEST_CASE("Oracle mass: random bodies agree with the engine's mass setup", "[oracle][mass]") {
  std::mt19937_64 random(14);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst_mass = 0.0;
  double worst_center = 0.0;
  double worst_moment = 0.0;
  for (int i = 0; i < 5000; ++i) {
    BodyDef def = body_of({});
    const int shapes = 1 + static_cast<int>(random() % 4);
    for (int k = 0; k < shapes; ++k) {
      const auto kind = static_cast<gp::test::RandomKind>(random() % gp::test::kRandomKinds);
      Shape shape = gp::test::random_shape(kind, random);
      // Shapes spread over a few metres of the body frame, as in the scenes' compound bodies.
      const Vec2 shift(4.0 * unit(random) - 2.0, 4.0 * unit(random) - 2.0);
      shape = std::visit(
          [&](const auto& g) -> Shape {
            using G = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<G, gp::Circle>) {
              return Shape::circle(g.radius, g.center + shift);
            } else if constexpr (std::is_same_v<G, gp::Segment>) {
              return Shape::segment(g.a + shift, g.b + shift, g.radius);
            } else {
              std::vector<Vec2> moved;
              for (int v = 0; v < g.count; ++v) moved.push_back(g.vertices[v] + shift);
              return Shape::polygon(moved);
            }
          },
          shape.geometry());
      def.shapes.push_back({shape, 0.0, 0.0, 0.1 + 10.0 * unit(random)});
    }
    if (random() % 4 == 0) def.mass = 0.5 + unit(random);
    if (random() % 4 == 0) def.moment = 0.5 + unit(random);
    const gp::MassSetup engine = gp::mass_setup(def);
    const gp::oracle::BodyMass oracle = gp::oracle::body_mass(def);
    INFO("body " << i);
    // Relative to the body's own scale: its mass, its size (≤ 6 m), its moment.
    const double mass_error = std::abs(oracle.mass - engine.mass) / std::max(engine.mass, 1e-300);
    const double center_error = (oracle.center - engine.local_center).norm() / 6.0;
    const double moment_error =
        std::abs(oracle.moment - engine.moment) / std::max(engine.moment, 1e-300);
    if (engine.mass == 0.0) {
      CHECK(oracle.mass == 0.0);
      CHECK(oracle.moment == engine.moment);
      continue;
    }
    worst_mass = std::max(worst_mass, mass_error);
    worst_center = std::max(worst_center, center_error);
    worst_moment = std::max(worst_moment, moment_error);
  }
  INFO("largest relative disagreement: mass " << worst_mass << ", centre " << worst_center
                                              << " (of 6 m), moment " << worst_moment);
  // Sums of a few dozen products in another order: measured 4.3e-16 (mass), 1.2e-16 (centre) and
  // 3.1e-15 (moment, which cancels in the parallel-axis shift); about 10 times those.
  CHECK(worst_mass <= 5e-15);
  CHECK(worst_center <= 2e-15);
  CHECK(worst_moment <= 3e-14);
}

}  // namespace test_oracle_mass
}  // namespace
