#include "engine/geometry/world_shape.hpp"

#include <variant>

namespace gp {

namespace {

WorldShape place(const Circle& circle, const Transform& transform) {
  const Vec2 center = transform.apply(circle.center);
  const Vec2 extent(circle.radius, circle.radius);
  return {Circle{center, circle.radius}, Aabb{center - extent, center + extent}};
}

WorldShape place(const PolygonView& polygon, const Transform& transform) {
  ConvexPolygon placed{};
  placed.count = static_cast<int>(polygon.vertices.size());
  const Aabb bounds =
      place_polygon(polygon, transform, std::span(placed.vertices).first(polygon.vertices.size()),
                    std::span(placed.normals).first(polygon.vertices.size()));
  return {placed, bounds};
}

WorldShape place(const Segment& segment, const Transform& transform) {
  const Vec2 a = transform.apply(segment.a);
  const Vec2 b = transform.apply(segment.b);
  const Vec2 extent(segment.radius, segment.radius);
  return {Segment{a, b, segment.radius}, Aabb{a.cwiseMin(b) - extent, a.cwiseMax(b) + extent}};
}

}  // namespace

WorldShape to_world(const GeometryView& local, const Transform& transform) {
  return std::visit([&](const auto& geometry) { return place(geometry, transform); }, local);
}

Aabb place_polygon(const PolygonView& polygon, const Transform& transform, std::span<Vec2> vertices,
                   std::span<Vec2> normals) {
  const std::size_t count = polygon.vertices.size();
  for (std::size_t i = 0; i < count; ++i) {
    vertices[i] = transform.apply(polygon.vertices[i]);
    normals[i] = transform.rotate(polygon.normals[i]);
  }
  Aabb bounds{vertices[0], vertices[0]};
  for (std::size_t i = 1; i < count; ++i) {
    bounds.min = bounds.min.cwiseMin(vertices[i]);
    bounds.max = bounds.max.cwiseMax(vertices[i]);
  }
  return bounds;
}

}  // namespace gp
