#pragma once
// A GeometryView packed into 48 bytes for the arrays that hold one per shape: the variant takes
// 64, as Vec2's 16-byte alignment pads a segment (40 bytes of numbers) to 48 and then the variant's
// index to 64. Unpacking gives back the same numbers.

#include <cstdint>
#include <span>
#include <variant>

#include "scene/shape.hpp"

namespace gp {

class PackedGeometry {
 public:
  PackedGeometry() : circle_{0.0, 0.0, 0.0}, kind_(ShapeKind::kCircle) {}
  /// Packs a geometry; a polygon's vertices, then as many normals right after them, stay where
  /// they are stored.
  explicit PackedGeometry(const Circle& circle)
      : circle_{circle.center.x(), circle.center.y(), circle.radius}, kind_(ShapeKind::kCircle) {}
  explicit PackedGeometry(const Segment& segment)
      : segment_{segment.a.x(), segment.a.y(), segment.b.x(), segment.b.y(), segment.radius},
        kind_(ShapeKind::kSegment) {}
  explicit PackedGeometry(const PolygonView& polygon)
      : polygon_{polygon.vertices.data(), static_cast<std::uint32_t>(polygon.vertices.size())},
        kind_(ShapeKind::kPolygon) {}

  /// Packs any geometry; as above, a polygon's normals must follow its vertices.
  explicit PackedGeometry(const GeometryView& geometry)
      : PackedGeometry(std::visit([](const auto& g) { return PackedGeometry(g); }, geometry)) {}

  ShapeKind kind() const { return kind_; }

  GeometryView view() const {
    switch (kind_) {
      case ShapeKind::kCircle:
        return circle();
      case ShapeKind::kSegment:
        return segment();
      case ShapeKind::kPolygon:
        break;
    }
    return polygon();
  }
  /// Viewed where a GeometryView is asked for, so that a packed geometry is read as any other.
  operator GeometryView() const { return view(); }
  /// The geometry of each kind, for a caller that has switched on kind() already.
  // The points are loaded whole, not built from two scalars: that goes through the stack, and the
  // wide load of the view made from them stalls on the two narrow stores.
  Circle circle() const { return {Vec2::Map(&circle_.x), circle_.radius}; }
  Segment segment() const {
    return {Vec2::Map(&segment_.ax), Vec2::Map(&segment_.bx), segment_.radius};
  }
  PolygonView polygon() const {
    return {std::span(polygon_.points, polygon_.count),
            std::span(polygon_.points + polygon_.count, polygon_.count)};
  }

 private:
  struct Disc {
    double x, y, radius;
  };
  struct Line {
    double ax, ay, bx, by, radius;
  };
  struct Outline {
    const Vec2* points;  // the vertices, then the normals
    std::uint32_t count;
  };
  union {
    Disc circle_;
    Line segment_;
    Outline polygon_;
  };
  ShapeKind kind_;
};

}  // namespace gp
