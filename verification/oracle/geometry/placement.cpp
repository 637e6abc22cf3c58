#include "verification/oracle/geometry/placement.hpp"

#include <algorithm>

#include "verification/oracle/model/rotation.hpp"

namespace gp::oracle {

std::vector<Vec2> placed_vertices(const Hull& hull, const Pose& pose) {
  std::vector<Vec2> placed;
  for (const Vec2& v : hull.vertices) placed.push_back(pose.position + rotated(v, pose.angle));
  return placed;
}

Vec2 edge_normal(std::span<const Vec2> vertices, int edge) {
  const int n = static_cast<int>(vertices.size());
  const Vec2 along = vertices[(edge + 1) % n] - vertices[edge];
  return Vec2(along.y(), -along.x()).normalized();
}

double reach(const Hull& hull) {
  double r = 0.0;
  for (const Vec2& v : hull.vertices) r = std::max(r, v.norm());
  return r + hull.radius;
}

}  // namespace gp::oracle
