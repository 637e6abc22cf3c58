// The stability metrics of the hard cases of other solvers, each against a hand computation on
// bodies placed by hand.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "verification/suite/stability_metrics.hpp"

namespace {
namespace test_stability_metrics {

using gp::BodyState;
using gp::BodyType;
using gp::Shape;
using gp::Vec2;
using gp::peers::PeerBody;

PeerBody body(BodyType type, const Shape& shape, double mass = 1.0, double moment = 1.0) {
  return {"b", type, mass, moment, {}, {{shape, 0.0, 0.0}}, Vec2::Zero(), 0.0, std::nullopt};
}

BodyState at(const Vec2& position, double angle = 0.0, const Vec2& velocity = Vec2::Zero(),
             double angular_velocity = 0.0) {
  return {position, angle, velocity, angular_velocity};
}

const Shape kUnitBox = Shape::box(1.0, 1.0);
const Shape kDisc = Shape::circle(0.5);

using gp::verification::kinetic_energy;
using gp::verification::largest_drift;
using gp::verification::largest_overlap;
using gp::verification::largest_speed;

TEST_CASE("largest_overlap: the shortest separating translation of shapes placed by hand",
          "[stability]") {
  const auto dynamic_box = body(BodyType::Dynamic, kUnitBox);
  SECTION("two unit boxes 0.8 m apart side by side, 0.1 m offset: 0.2 m along x") {
    CHECK(largest_overlap({dynamic_box, dynamic_box}, {at({0, 0}), at({0.8, 0.1})}) ==
          Approx(0.2).epsilon(1e-12));
  }
  SECTION("a box turned 45° whose corner dips 0.1 m into a box below: 0.1 m") {
    const double corner = std::numbers::sqrt2 / 2;
    CHECK(largest_overlap({dynamic_box, dynamic_box},
                          {at({0, 0}), at({0.3, 0.5 + corner - 0.1}, std::numbers::pi / 4)}) ==
          Approx(0.1).epsilon(1e-12));
  }
  SECTION("two discs of 0.5 m 0.7 m apart: 0.3 m") {
    const auto d = body(BodyType::Dynamic, kDisc);
    CHECK(largest_overlap({d, d}, {at({0, 0}), at({0.7 * 0.6, 0.7 * 0.8})}) ==
          Approx(0.3).epsilon(1e-12));
  }
  SECTION("a disc over a box's corner: its radius less its distance to the corner") {
    const auto d = body(BodyType::Dynamic, kDisc);
    const double expected = 0.5 - 0.3 * std::numbers::sqrt2;
    CHECK(largest_overlap({dynamic_box, d}, {at({0, 0}), at({0.8, 0.8})}) ==
          Approx(expected).epsilon(1e-12));
  }
  SECTION("the deepest pair counts; static pairs and shapes apart do not") {
    const auto ground = body(BodyType::Static, kUnitBox);
    CHECK(largest_overlap({ground, ground, dynamic_box, dynamic_box},
                          {at({0, 0}), at({0.5, 0}), at({0, 0.9}), at({3, 0})}) ==
          Approx(0.1).epsilon(1e-12));
    CHECK(largest_overlap({dynamic_box, dynamic_box}, {at({0, 0}), at({1.01, 0})}) == 0.0);
  }
}

TEST_CASE("largest_overlap over a crowd is the deepest of its pairs measured two at a time",
          "[stability]") {
  // 300 discs and boxes scattered at random over a 20 m square, overlapping here and there, a
  // static floor among them; the sweep along x must find every pair the pairs one by one find.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> place(-10.0, 10.0);
  std::uniform_real_distribution<double> turn(0.0, 6.0);
  std::vector<PeerBody> bodies{body(BodyType::Static, Shape::box(20.0, 0.5))};
  std::vector<BodyState> states{at({0.0, -9.0})};
  for (int i = 0; i < 300; ++i) {
    bodies.push_back(body(BodyType::Dynamic, i % 3 == 0 ? kUnitBox : kDisc));
    states.push_back(at({place(random), place(random)}, turn(random)));
  }
  double deepest = 0.0;
  int overlapping = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      const double pair = largest_overlap({bodies[i], bodies[j]}, {states[i], states[j]});
      deepest = std::max(deepest, pair);
      overlapping += pair > 0.0 ? 1 : 0;
    }
  }
  INFO(overlapping << " pairs overlap");
  CHECK(overlapping > 50);
  CHECK(largest_overlap(bodies, states) == deepest);
}

TEST_CASE("largest_drift and largest_speed: the farthest and fastest dynamic body", "[stability]") {
  const auto moving = body(BodyType::Dynamic, kUnitBox);
  const auto ground = body(BodyType::Static, kUnitBox);
  const std::vector<PeerBody> bodies{moving, moving, ground};
  const std::vector<BodyState> start{at({1, 1}), at({0, 0}), at({0, 0})};
  const std::vector<BodyState> now{at({1, 2}, 0, {0, 1}), at({3, 4}, 0, {-6, 8}),
                                   at({100, 0}, 0, {100, 0})};
  CHECK(largest_drift(bodies, start, now) == Approx(5.0).epsilon(1e-15));
  CHECK(largest_speed(bodies, now) == Approx(10.0).epsilon(1e-15));
}

TEST_CASE("kinetic_energy: ½ m v² + ½ I ω² summed over the dynamic bodies", "[stability]") {
  const auto spinning = body(BodyType::Dynamic, kUnitBox, 2.0, 0.5);
  const auto no_rotation =
      body(BodyType::Dynamic, kUnitBox, 2.0, std::numeric_limits<double>::infinity());
  const auto ground = body(BodyType::Static, kUnitBox, std::numeric_limits<double>::infinity());
  // 2 kg at 5 m/s: 25 J; 0.5 kg·m² at 2 rad/s: 1 J; the body that cannot rotate: 25 J.
  CHECK(kinetic_energy({spinning, no_rotation, ground},
                       {at({0, 0}, 0, {3, 4}, 2), at({0, 0}, 0, {0, 5}, 0), at({0, 0})}) ==
        Approx(51.0).epsilon(1e-15));
}

}  // namespace test_stability_metrics
}  // namespace
