#include "engine/geometry/shape_extent.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <variant>

namespace gp {

double reach(const GeometryView& shape) {
  return std::visit(
      [](const auto& g) -> double {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Circle>) {
          return g.center.norm() + g.radius;
        } else if constexpr (std::is_same_v<G, Segment>) {
          return std::max(g.a.norm(), g.b.norm()) + g.radius;
        } else {
          double r = 0.0;
          for (const Vec2& v : g.vertices) r = std::max(r, v.norm());
          return r;
        }
      },
      shape);
}

double half_thickness(const GeometryView& shape) {
  return std::visit(
      [](const auto& g) -> double {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Circle> || std::is_same_v<G, Segment>) {
          return g.radius;
        } else {
          const auto count = static_cast<int>(g.vertices.size());
          Vec2 centroid = Vec2::Zero();
          for (int i = 0; i < count; ++i) centroid += g.vertices[i] / count;
          double least = std::numeric_limits<double>::infinity();
          for (int i = 0; i < count; ++i) {
            least = std::min(least, g.normals[i].dot(g.vertices[i] - centroid));
          }
          return least;
        }
      },
      shape);
}

}  // namespace gp
