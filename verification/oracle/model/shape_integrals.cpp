#include "verification/oracle/model/shape_integrals.hpp"

#include <numbers>

namespace gp::oracle {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

ShapeIntegrals disc_integrals(const Vec2& center, double radius) {
  const double area = kPi * radius * radius;
  return {area, center, 0.5 * area * radius * radius};
}

ShapeIntegrals polygon_integrals(std::span<const Vec2> vertices) {
  // The fan's centre inside the polygon keeps every term of the order of the polygon's size, so a
  // polygon far from its body's origin loses nothing to cancellation.
  Vec2 hub = Vec2::Zero();
  for (const Vec2& v : vertices) hub += v;
  hub /= static_cast<double>(vertices.size());
  double area = 0.0;
  Vec2 first_moment = Vec2::Zero();  // m³, about the hub
  double polar_about_hub = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2 a = vertices[i] - hub;
    const Vec2 b = vertices[(i + 1) % vertices.size()] - hub;
    const double triangle_area = 0.5 * cross(a, b);
    area += triangle_area;
    first_moment += triangle_area * (a + b) / 3.0;
    polar_about_hub += triangle_area * (a.squaredNorm() + a.dot(b) + b.squaredNorm()) / 6.0;
  }
  const Vec2 offset = first_moment / area;  // centroid − hub
  return {area, hub + offset, polar_about_hub - area * offset.squaredNorm()};
}

ShapeIntegrals capsule_integrals(const Vec2& a, const Vec2& b, double radius) {
  const double length = (b - a).norm();
  const double width = 2.0 * radius;
  const double rectangle_area = width * length;
  const double rectangle_polar = rectangle_area * (length * length + width * width) / 12.0;
  // A half disc: polar moment π r⁴ / 4 about the centre of its circle, whose centroid lies
  // 4r / 3π from that centre, away from the segment's middle by L/2 + 4r / 3π.
  const double half_area = 0.5 * kPi * radius * radius;
  const double to_centroid = 4.0 * radius / (3.0 * kPi);
  const double half_about_centroid =
      0.25 * kPi * radius * radius * radius * radius - half_area * to_centroid * to_centroid;
  const double out = 0.5 * length + to_centroid;
  const double half_polar = half_about_centroid + half_area * out * out;
  return {rectangle_area + 2.0 * half_area, 0.5 * (a + b), rectangle_polar + 2.0 * half_polar};
}

}  // namespace gp::oracle
