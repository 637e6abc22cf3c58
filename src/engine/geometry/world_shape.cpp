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
  const auto count = static_cast<std::size_t>(polygon.count);
  const Aabb bounds = place_polygon(polygon, transform, std::span(placed.vertices).first(count),
                                    std::span(placed.normals).first(count));
  return {placed, bounds};
}

WorldShape place(const Segment& segment, const Transform& transform) {
  const Vec2 a = transform.apply(segment.a);
  const Vec2 b = transform.apply(segment.b);
  const Vec2 extent(segment.radius, segment.radius);
  return {Segment{a, b, segment.radius}, Aabb{a.cwiseMin(b) - extent, a.cwiseMax(b) + extent}};
}

WorldGeometryView view_of(const Circle& circle) {
  return circle;
}

WorldGeometryView view_of(const ConvexPolygon& polygon) {
  const auto count = static_cast<std::size_t>(polygon.count);
  return PolygonView{std::span(polygon.vertices).first(count),
                     std::span(polygon.normals).first(count)};
}

WorldGeometryView view_of(const Segment& segment) {
  return segment;
}

}  // namespace

WorldShapeView::WorldShapeView(const WorldShape& shape)
    : geometry(std::visit([](const auto& g) { return view_of(g); }, shape.geometry)),
      bounds(shape.bounds) {}

WorldShape to_world(const Shape& shape, const Transform& transform) {
  return std::visit([&](const auto& geometry) { return place(geometry, transform); },
                    shape.geometry());
}

Aabb place_polygon(const ConvexPolygon& polygon, const Transform& transform,
                   std::span<Vec2> vertices, std::span<Vec2> normals) {
  for (int i = 0; i < polygon.count; ++i) {
    vertices[i] = transform.apply(polygon.vertices[i]);
    normals[i] = transform.rotate(polygon.normals[i]);
  }
  Aabb bounds{vertices[0], vertices[0]};
  for (int i = 1; i < polygon.count; ++i) {
    bounds.min = bounds.min.cwiseMin(vertices[i]);
    bounds.max = bounds.max.cwiseMax(vertices[i]);
  }
  return bounds;
}

}  // namespace gp
