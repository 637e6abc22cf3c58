#include "engine/geometry/shape_extent.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <variant>

namespace gp {

namespace {

// The farthest point of each kind of core from the centre of mass [m].
double core_reach_of(const Circle& g) {
  return g.center.norm();
}
double core_reach_of(const Segment& g) {
  return std::max(g.a.norm(), g.b.norm());
}
double core_reach_of(const PolygonView& g) {
  double r = 0.0;
  for (const Vec2& v : g.vertices) r = std::max(r, v.norm());
  return r;
}

}  // namespace

double reach(const GeometryView& shape) {
  return std::visit(
      [](const auto& g) -> double {
        if constexpr (std::is_same_v<std::decay_t<decltype(g)>, PolygonView>) {
          return core_reach_of(g);
        } else {
          return core_reach_of(g) + g.radius;
        }
      },
      shape);
}

double core_reach(const GeometryView& shape) {
  return std::visit([](const auto& g) { return core_reach_of(g); }, shape);
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
