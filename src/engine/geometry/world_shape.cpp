#include "engine/geometry/world_shape.hpp"

#include <variant>

namespace gp {

namespace {

WorldShape place(const Circle& circle, const Transform& transform) {
  const Vec2 center = transform.apply(circle.center);
  const Vec2 extent(circle.radius, circle.radius);
  return {Circle{center, circle.radius}, Aabb{center - extent, center + extent}};
}

WorldShape place(const ConvexPolygon& polygon, const Transform& transform) {
  ConvexPolygon placed{};
  placed.count = polygon.count;
  for (int i = 0; i < polygon.count; ++i) {
    placed.vertices[i] = transform.apply(polygon.vertices[i]);
    placed.normals[i] = transform.rotate(polygon.normals[i]);
  }
  Aabb bounds{placed.vertices[0], placed.vertices[0]};
  for (int i = 1; i < placed.count; ++i) {
    bounds.min = bounds.min.cwiseMin(placed.vertices[i]);
    bounds.max = bounds.max.cwiseMax(placed.vertices[i]);
  }
  return {placed, bounds};
}

WorldShape place(const Segment& segment, const Transform& transform) {
  const Vec2 a = transform.apply(segment.a);
  const Vec2 b = transform.apply(segment.b);
  const Vec2 extent(segment.radius, segment.radius);
  return {Segment{a, b, segment.radius}, Aabb{a.cwiseMin(b) - extent, a.cwiseMax(b) + extent}};
}

}  // namespace

WorldShape to_world(const Shape& shape, const Transform& transform) {
  return std::visit([&](const auto& geometry) { return place(geometry, transform); },
                    shape.geometry());
}

}  // namespace gp
