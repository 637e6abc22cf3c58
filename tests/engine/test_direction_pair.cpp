// GD:impulse evaluated on two directions at once (engine/solver/direction_pair.hpp), as the
// contact preparation takes a point's normal and tangent effective masses: each lane the bits of
// the model function evaluated on its direction alone.

#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>

#include "engine/solver/direction_pair.hpp"
#include "gamephysics/models/gd/collision_impulse.hpp"

namespace {
namespace test_direction_pair {

using gp::DoublePair;
using gp::Vec2;
using gp::Vec2Pair;

TEST_CASE("GD:impulse on a pair of directions gives each direction's own result to the bit",
          "[GD:impulse]") {
  std::mt19937_64 random(20261201);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto vector = [&] { return Vec2(unit(random), unit(random)); };
  int differing = 0;
  for (int k = 0; k < 10000; ++k) {
    // Directions of any length and angle (the engine's are unit, 90° apart), velocities and
    // arms at random, and now and then an immovable body (inverse mass and moment 0).
    const Vec2 first = vector();
    const Vec2 second = vector();
    const Vec2 velocity_first = vector();
    const Vec2 velocity_second = vector();
    const Vec2 arm_a = vector();
    const Vec2 arm_b = vector();
    const bool fixed_b = k % 5 == 0;
    const double inverse_mass_a = 1.5 + unit(random);
    const double inverse_mass_b = fixed_b ? 0.0 : 1.5 + unit(random);
    const double inverse_moment_a = 6.0 + unit(random);
    const double inverse_moment_b = fixed_b ? 0.0 : 6.0 + unit(random);
    const double restitution = 0.5 + 0.5 * unit(random);

    const Vec2Pair directions{{first.x(), second.x()}, {first.y(), second.y()}};
    const Vec2Pair velocities{{velocity_first.x(), velocity_second.x()},
                              {velocity_first.y(), velocity_second.y()}};
    const DoublePair both =
        gp::gd::collision_impulse<DoublePair, double, Vec2Pair, Vec2Pair, double, double, Vec2>(
            restitution, velocities, directions, inverse_mass_a, inverse_mass_b, inverse_moment_a,
            inverse_moment_b, arm_a, arm_b);
    const auto alone = [&](const Vec2& velocity, const Vec2& direction) {
      return gp::gd::collision_impulse(restitution, velocity, direction, inverse_mass_a,
                                       inverse_mass_b, inverse_moment_a, inverse_moment_b, arm_a,
                                       arm_b);
    };
    const double expected[2] = {alone(velocity_first, first), alone(velocity_second, second)};
    for (int lane = 0; lane < 2; ++lane) {
      differing +=
          std::bit_cast<std::uint64_t>(both[lane]) != std::bit_cast<std::uint64_t>(expected[lane]);
    }
  }
  CHECK(differing == 0);
}

TEST_CASE("The lanes' cross, dot and squared norm follow the vectors' own, lane by lane") {
  // By hand: a = (3, −2); b = ((1, 4), (−5, 0.5)).
  const Vec2 a(3.0, -2.0);
  const Vec2Pair b{{1.0, -5.0}, {4.0, 0.5}};
  const DoublePair cross = gp::cross(a, b);
  CHECK(cross[0] == 3.0 * 4.0 - (-2.0) * 1.0);   // 14
  CHECK(cross[1] == 3.0 * 0.5 - (-2.0) * -5.0);  // −8.5
  const DoublePair dot = gp::dot(b, b);
  CHECK(dot[0] == 17.0);
  CHECK(dot[1] == 25.25);
  const DoublePair squared = gp::squared_norm(-b);
  CHECK(squared[0] == 17.0);
  CHECK(squared[1] == 25.25);
}

}  // namespace test_direction_pair
}  // namespace
