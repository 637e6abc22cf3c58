#include "engine/solver/contact_islands.hpp"

#include <algorithm>
#include <numeric>

#include "engine/capacity.hpp"

namespace gp {

void ContactIslands::find(const ContactSet& contacts, const BodyInertia& inertia) {
  const std::size_t bodies = inertia.inverse_mass.size();
  parent.resize(bodies);
  std::iota(parent.begin(), parent.end(), BodyId{0});
  for (const Contact& c : contacts) {
    if (movable(inertia, c.body_a) && movable(inertia, c.body_b)) {
      const BodyId a = root_of(parent, c.body_a);
      const BodyId b = root_of(parent, c.body_b);
      parent[std::max(a, b)] = std::min(a, b);
    }
  }
  // Every body pointing at its root: an island is then one look-up away. A root is the
  // island's lowest body id, so roots come before their bodies in this loop.
  for (BodyId b = 0; b < bodies; ++b) parent[b] = parent[parent[b]];
  const auto root = [&](const Contact& c) {
    return parent[movable(inertia, c.body_a) ? c.body_a : c.body_b];
  };
  points.assign(bodies, 0);
  island_start.assign(bodies, 0);
  island_end.assign(bodies, 0);
  std::vector<std::uint32_t>& counts = island_end;
  for (const Contact& c : contacts) {
    const BodyId r = root(c);
    points[r] += static_cast<std::uint32_t>(c.count());
    ++counts[r];
  }
  std::uint32_t next = 0;
  roots.clear();
  for (BodyId r = 0; r < bodies; ++r) {
    if (counts[r] > 0) append(roots, r);
    island_start[r] = next;
    next += counts[r];
    counts[r] = island_start[r];
  }
  order.resize(contacts.size());
  for (std::uint32_t i = 0; i < contacts.size(); ++i) order[island_end[root(contacts[i])]++] = i;
}

}  // namespace gp
