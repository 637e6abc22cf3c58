#include "random_shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace gp::test {

namespace {

constexpr double kPi = std::numbers::pi;

double uniform(std::mt19937_64& random, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(random);
}

Vec2 small_offset(std::mt19937_64& random) {
  return {uniform(random, -0.05, 0.05), uniform(random, -0.05, 0.05)};
}

/// Vertices on an ellipse (so in convex position) at sorted angles no closer than 0.2 rad and no
/// gap wider than π − 0.2, so that the polygon holds the ellipse's centre well inside.
Shape random_polygon(std::mt19937_64& random) {
  const int count = std::uniform_int_distribution<int>(3, 8)(random);
  const double a = uniform(random, 0.3, 1.2);
  const double b = uniform(random, 0.3, 1.2);
  const double turn = uniform(random, 0.0, 2.0 * kPi);
  for (;;) {
    std::vector<double> angles;
    for (int i = 0; i < count; ++i) angles.push_back(uniform(random, 0.0, 2.0 * kPi));
    std::sort(angles.begin(), angles.end());
    bool spread = true;
    for (int i = 0; i < count; ++i) {
      const double gap =
          i + 1 < count ? angles[i + 1] - angles[i] : angles[0] + 2 * kPi - angles[i];
      spread = spread && gap >= 0.2 && gap <= kPi - 0.2;
    }
    if (!spread) continue;
    std::vector<Vec2> vertices;
    for (const double angle : angles) {
      const Vec2 v(a * std::cos(angle), b * std::sin(angle));
      vertices.emplace_back(std::cos(turn) * v.x() - std::sin(turn) * v.y(),
                            std::sin(turn) * v.x() + std::cos(turn) * v.y());
    }
    try {
      return Shape::polygon(vertices);
    } catch (const std::invalid_argument&) {
      // nearly collinear vertices: draw again
    }
  }
}

Shape random_segment(std::mt19937_64& random, double radius, double shortest, double longest) {
  const double half = 0.5 * uniform(random, shortest, longest);
  const double angle = uniform(random, 0.0, 2.0 * kPi);
  const Vec2 end(half * std::cos(angle), half * std::sin(angle));
  // The origin stays on the core: slide along it rather than off it.
  const Vec2 middle = uniform(random, -0.2, 0.2) * end;
  return Shape::segment(middle + end, middle - end, radius);
}

}  // namespace

std::string_view kind_name(RandomKind kind) {
  constexpr std::array<std::string_view, kRandomKinds> kNames{"disc", "box", "polygon", "capsule",
                                                              "line"};
  return kNames[static_cast<int>(kind)];
}

Shape random_shape(RandomKind kind, std::mt19937_64& random) {
  switch (kind) {
    case RandomKind::Disc:
      return Shape::circle(uniform(random, 0.1, 1.0), small_offset(random));
    case RandomKind::Box:
      return Shape::box(uniform(random, 0.2, 2.0), uniform(random, 0.2, 2.0), small_offset(random));
    case RandomKind::Polygon:
      return random_polygon(random);
    case RandomKind::Capsule:
      return random_segment(random, uniform(random, 0.05, 0.5), 0.2, 2.0);
    case RandomKind::Line:
      break;
  }
  return random_segment(random, 0.0, 0.5, 3.0);
}

}  // namespace gp::test
