#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/geometry/placement.hpp"

#include <algorithm>
#include <cmath>

namespace gp::oracle {

ActiveContact make_active_contact(const World& world, const HullPair& pair, std::size_t pair_index,
                                  const Feature& feature) {
  ActiveContact c{};
  c.pair = pair_index;
  c.feature = feature;
  const bool a_has_vertex = feature.kind != Feature::Kind::EdgeVertex;
  c.first = a_has_vertex ? pair.body_a : pair.body_b;
  c.second = a_has_vertex ? pair.body_b : pair.body_a;
  c.first_hull = a_has_vertex ? pair.hull_a : pair.hull_b;
  c.second_hull = a_has_vertex ? pair.hull_b : pair.hull_a;
  c.first_vertex = a_has_vertex ? feature.a : feature.b;
  c.second_feature = a_has_vertex ? feature.b : feature.a;
  const Hull& first = world.bodies[c.first].hulls[c.first_hull];
  const Hull& second = world.bodies[c.second].hulls[c.second_hull];
  const auto& v2 = second.vertices;
  c.vertex = first.vertices[static_cast<std::size_t>(c.first_vertex)];
  c.on_edge = feature.kind != Feature::Kind::VertexVertex;
  c.anchor = v2[static_cast<std::size_t>(c.second_feature)];
  if (c.on_edge) {
    c.edge_end = v2[static_cast<std::size_t>(c.second_feature + 1) % v2.size()];
    c.edge_normal = edge_normal(v2, c.second_feature);
  }
  c.first_radius = first.radius;
  c.radius = first.radius + second.radius;
  c.friction = std::sqrt(first.friction * second.friction);
  c.restitution = std::max(first.restitution, second.restitution);
  return c;
}

bool same_contact(const ActiveContact& a, const ActiveContact& b) {
  return a.pair == b.pair && a.feature.kind == b.feature.kind && a.feature.a == b.feature.a &&
         a.feature.b == b.feature.b;
}

}  // namespace gp::oracle
