#include "engine/geometry/world_shape.hpp"

#include <variant>

namespace gp {

namespace {

WorldShape place(const Circle& circle, const Transform& transform) {
  const Circle placed = moved(circle, transform);
  return {placed, bounds_of(placed)};
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
  const Segment placed = moved(segment, transform);
  return {placed, bounds_of(placed)};
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
  for (std::size_t i = 1; i < count; ++i) bounds = bounds.grown_to(vertices[i]);
  return bounds;
}

Aabb placed_bounds(const PolygonView& polygon, const Transform& transform) {
  const Vec2 first = transform.apply(polygon.vertices[0]);
  Aabb bounds{first, first};
  for (std::size_t i = 1; i < polygon.vertices.size(); ++i) {
    bounds = bounds.grown_to(transform.apply(polygon.vertices[i]));
  }
  return bounds;
}

}  // namespace gp
