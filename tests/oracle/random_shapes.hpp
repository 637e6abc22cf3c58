#pragma once
// Seeded random shapes of every kind, for the differential tests of the oracle's model against
// the engine's: sizes from 0.1 m to 2 m, each shape containing its frame's origin.

#include <random>
#include <string_view>

#include "scene/shape.hpp"

namespace gp::test {

/// Disc, box, convex polygon (3 to 8 vertices), capsule, bare segment.
enum class RandomKind { Disc, Box, Polygon, Capsule, Line };
inline constexpr int kRandomKinds = 5;

std::string_view kind_name(RandomKind kind);

/// A shape of `kind` whose core contains the origin (so that two shapes placed at one point
/// overlap), within 2 m of it.
Shape random_shape(RandomKind kind, std::mt19937_64& random);

}  // namespace gp::test
