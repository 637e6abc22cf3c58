#include "scene/shape.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gp {

namespace {

// Tolerance for "same point", "zero area" and "collinear", relative to the polygon's size so that
// the rules mean the same at any scale: round-off in metre-scale input is far below it.
constexpr double kRelativeTolerance = 1e-9;

std::string to_text(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

std::string to_text(const Vec2& point) {
  std::ostringstream out;
  out.precision(12);
  out << '(' << point.x() << ", " << point.y() << ')';
  return out.str();
}

[[noreturn]] void reject(const std::string& message) {
  throw std::invalid_argument(message);
}

void require_finite(const Vec2& point, const std::string& what) {
  if (!point.allFinite()) reject(what + " must be finite, got " + to_text(point));
}

void require_positive(double value, const std::string& what) {
  if (!std::isfinite(value) || value <= 0.0) {
    reject(what + " must be finite and > 0, got " + to_text(value));
  }
}

ConvexPolygon make_polygon(std::span<const Vec2> counter_clockwise) {
  ConvexPolygon polygon{};
  polygon.count = static_cast<int>(counter_clockwise.size());
  for (int i = 0; i < polygon.count; ++i) {
    const Vec2 edge = counter_clockwise[(i + 1) % polygon.count] - counter_clockwise[i];
    polygon.vertices[i] = counter_clockwise[i];
    polygon.normals[i] = Vec2(edge.y(), -edge.x()).normalized();
  }
  return polygon;
}

}  // namespace

Shape Shape::circle(double radius, const Vec2& center) {
  require_positive(radius, "circle radius");
  require_finite(center, "circle centre");
  return Shape(Circle{center, radius});
}

Shape Shape::polygon(std::span<const Vec2> vertices) {
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    require_finite(vertices[i], "polygon vertex " + std::to_string(i));
  }
  Vec2 lower = Vec2::Constant(0.0);
  Vec2 upper = Vec2::Constant(0.0);
  if (!vertices.empty()) {
    lower = upper = vertices.front();
    for (const Vec2& v : vertices) {
      lower = lower.cwiseMin(v);
      upper = upper.cwiseMax(v);
    }
  }
  const double tolerance = kRelativeTolerance * (upper - lower).norm();

  std::vector<Vec2> distinct;
  for (const Vec2& v : vertices) {
    if (distinct.empty() || (v - distinct.back()).norm() > tolerance) distinct.push_back(v);
  }
  while (distinct.size() > 1 && (distinct.front() - distinct.back()).norm() <= tolerance) {
    distinct.pop_back();
  }
  const int count = static_cast<int>(distinct.size());
  if (count < 3) {
    reject("polygon needs at least 3 distinct vertices, got " + std::to_string(count));
  }
  if (count > kMaxPolygonVertices) {
    reject("polygon may have at most " + std::to_string(kMaxPolygonVertices) + " vertices, got " +
           std::to_string(count));
  }

  double twice_area = 0.0;
  for (int i = 0; i < count; ++i) twice_area += cross(distinct[i], distinct[(i + 1) % count]);
  if (std::abs(twice_area) <= tolerance * (upper - lower).norm()) {
    reject("polygon area must be > 0 (vertices not all collinear), got " +
           to_text(0.5 * twice_area));
  }
  if (twice_area < 0.0) std::reverse(distinct.begin(), distinct.end());

  for (int k = 0; k < count; ++k) {
    const Vec2& previous = distinct[(k + count - 1) % count];
    const Vec2& vertex = distinct[k];
    const Vec2& next = distinct[(k + 1) % count];
    // Twice the area of (previous, vertex, next) over its base: the corner's height.
    if (cross(vertex - previous, next - vertex) <= tolerance * (next - previous).norm()) {
      reject("polygon must be strictly convex (no reflex or straight corner): vertex " +
             to_text(vertex) + " is not");
    }
  }
  // All corners turning left still lets through a star that winds round twice.
  for (int i = 0; i < count; ++i) {
    const Vec2& start = distinct[i];
    const Vec2& end = distinct[(i + 1) % count];
    for (int k = 0; k < count; ++k) {
      if (k == i || k == (i + 1) % count) continue;
      if (cross(end - start, distinct[k] - start) <= 0.0) {
        reject("polygon must not intersect itself: vertex " + to_text(distinct[k]) +
               " is outside the edge from " + to_text(start) + " to " + to_text(end));
      }
    }
  }
  return Shape(make_polygon(distinct));
}

Shape Shape::box(double width, double height, const Vec2& center) {
  require_positive(width, "box width");
  require_positive(height, "box height");
  require_finite(center, "box centre");
  const double hx = 0.5 * width;
  const double hy = 0.5 * height;
  const std::array<Vec2, 4> corners{center + Vec2(-hx, -hy), center + Vec2(hx, -hy),
                                    center + Vec2(hx, hy), center + Vec2(-hx, hy)};
  // Through the polygon rules too: a box far too thin for its offset rounds to a degenerate one.
  return polygon(corners);
}

Shape Shape::copy_of(const GeometryView& geometry) {
  if (const auto* circle = std::get_if<Circle>(&geometry)) {
    return Shape::circle(circle->radius, circle->center);
  }
  if (const auto* polygon = std::get_if<PolygonView>(&geometry)) {
    return Shape::polygon(polygon->vertices);
  }
  const auto& segment = std::get<Segment>(geometry);
  return Shape::segment(segment.a, segment.b, segment.radius);
}

GeometryView view_of(const ShapeGeometry& geometry) {
  if (const auto* polygon = std::get_if<ConvexPolygon>(&geometry)) {
    const auto count = static_cast<std::size_t>(polygon->count);
    return PolygonView{std::span(polygon->vertices).first(count),
                       std::span(polygon->normals).first(count)};
  }
  if (const auto* circle = std::get_if<Circle>(&geometry)) return *circle;
  return std::get<Segment>(geometry);
}

Shape Shape::segment(const Vec2& a, const Vec2& b, double radius) {
  require_finite(a, "segment end a");
  require_finite(b, "segment end b");
  if (!std::isfinite(radius) || radius < 0.0) {
    reject("segment radius must be finite and >= 0, got " + to_text(radius));
  }
  if ((b - a).norm() <= kRelativeTolerance * std::max(a.norm(), b.norm())) {
    reject("segment ends must be distinct, got a = " + to_text(a) + " and b = " + to_text(b));
  }
  return Shape(Segment{a, b, radius});
}

}  // namespace gp
