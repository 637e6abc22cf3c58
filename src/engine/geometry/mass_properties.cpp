#include "engine/geometry/mass_properties.hpp"

#include <numbers>
#include <variant>

namespace gp {

namespace {

MassProperties mass_of(const Circle& circle) {
  const double rr = circle.radius * circle.radius;
  return {std::numbers::pi * rr, circle.center, 0.5 * std::numbers::pi * rr * rr};
}

MassProperties mass_of(const ConvexPolygon& polygon) {
  // Fanning out from a vertex rather than the origin keeps the terms small for a polygon placed
  // far from its body's origin, so less cancels in the final parallel-axis shift.
  const Vec2& origin = polygon.vertices[0];
  double area = 0.0;
  Vec2 first_moment = Vec2::Zero();
  double polar_about_origin = 0.0;
  for (int i = 1; i + 1 < polygon.count; ++i) {
    const Vec2 a = polygon.vertices[i] - origin;
    const Vec2 b = polygon.vertices[i + 1] - origin;
    const double twice_triangle_area = cross(a, b);
    area += 0.5 * twice_triangle_area;
    first_moment += (0.5 * twice_triangle_area / 3.0) * (a + b);
    polar_about_origin +=
        twice_triangle_area * (a.squaredNorm() + a.dot(b) + b.squaredNorm()) / 12.0;
  }
  const Vec2 centroid_from_origin = first_moment / area;
  return {area, origin + centroid_from_origin,
          polar_about_origin - area * centroid_from_origin.squaredNorm()};
}

MassProperties mass_of(const Segment& segment) {
  const double r = segment.radius;
  const double length = (segment.b - segment.a).norm();
  const double rectangle_area = 2.0 * r * length;
  const double disc_area = std::numbers::pi * r * r;
  const double rectangle_polar = rectangle_area * (length * length + 4.0 * r * r) / 12.0;
  const double half_discs_polar =
      0.5 * disc_area * r * r + 0.25 * disc_area * length * length + 4.0 / 3.0 * r * r * r * length;
  return {rectangle_area + disc_area, 0.5 * (segment.a + segment.b),
          rectangle_polar + half_discs_polar};
}

}  // namespace

MassProperties mass_properties(const Shape& shape) {
  return std::visit([](const auto& geometry) { return mass_of(geometry); }, shape.geometry());
}

}  // namespace gp
