#include "engine/setup/shape_offset.hpp"

#include <array>

namespace gp {

Shape translated(const Shape& shape, const Vec2& offset) {
  return std::visit(
      [&offset](const auto& g) -> Shape {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Circle>) {
          return Shape::circle(g.radius, g.center + offset);
        } else if constexpr (std::is_same_v<G, Segment>) {
          return Shape::segment(g.a + offset, g.b + offset, g.radius);
        } else {
          std::array<Vec2, kMaxPolygonVertices> moved;
          for (int i = 0; i < g.count; ++i) moved[i] = g.vertices[i] + offset;
          return Shape::polygon(std::span<const Vec2>(moved.data(), g.count));
        }
      },
      shape.geometry());
}

}  // namespace gp
