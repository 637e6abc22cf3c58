#include "engine/solver/island_solver.hpp"

#include <algorithm>
#include <numeric>

namespace gp {

namespace {

BodyId root_of(std::vector<BodyId>& parent, BodyId body) {
  while (parent[body] != body) {
    parent[body] = parent[parent[body]];  // path halving keeps the trees flat
    body = parent[body];
  }
  return body;
}

bool movable(const BodyInertia& m, BodyId body) {
  return m.inverse_mass[body] > 0.0 || m.inverse_moment[body] > 0.0;
}

// Groups the contacts by island into scratch.order; scratch.island_start and scratch.points,
// indexed by an island's root body, give each island's first entry and its number of points.
void find_islands(const ContactSet& contacts, const BodyInertia& inertia, IslandScratch& scratch) {
  const std::size_t bodies = inertia.inverse_mass.size();
  scratch.parent.resize(bodies);
  std::iota(scratch.parent.begin(), scratch.parent.end(), BodyId{0});
  for (const Contact& c : contacts) {
    if (movable(inertia, c.body_a) && movable(inertia, c.body_b)) {
      const BodyId a = root_of(scratch.parent, c.body_a);
      const BodyId b = root_of(scratch.parent, c.body_b);
      scratch.parent[std::max(a, b)] = std::min(a, b);
    }
  }
  // Every body pointing at its root: an island is then one look-up away. A root is the
  // island's lowest body id, so roots come before their bodies in this loop.
  for (BodyId b = 0; b < bodies; ++b) scratch.parent[b] = scratch.parent[scratch.parent[b]];
  const auto root = [&](const Contact& c) {
    return scratch.parent[movable(inertia, c.body_a) ? c.body_a : c.body_b];
  };
  scratch.points.assign(bodies, 0);
  scratch.island_start.assign(bodies, 0);
  scratch.cursor.assign(bodies, 0);
  std::vector<std::uint32_t>& counts = scratch.cursor;
  for (const Contact& c : contacts) {
    const BodyId r = root(c);
    scratch.points[r] += static_cast<std::uint32_t>(c.count());
    ++counts[r];
  }
  std::uint32_t next = 0;
  for (std::size_t r = 0; r < bodies; ++r) {
    scratch.island_start[r] = next;
    next += counts[r];
    counts[r] = scratch.island_start[r];
  }
  scratch.order.resize(contacts.size());
  for (std::uint32_t i = 0; i < contacts.size(); ++i)
    scratch.order[counts[root(contacts[i])]++] = i;
}

// The normal impulses of the island of scratch.rows into scratch.impulse (solve_normal_lcp).
// Returns false where that finds none.
bool solve_island(const ContactSet& contacts, const BodyInertia& inertia, const MotionState& s,
                  IslandScratch& scratch) {
  const auto n = static_cast<Eigen::Index>(scratch.rows.size());
  auto k = scratch.k.topLeftCorner(n, n);
  auto w0 = scratch.residual.head(n);
  auto start = scratch.initial.head(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Contact& ci = contacts[scratch.rows[i].contact];
    const ContactPointState& pi = contacts.points(ci)[scratch.rows[i].point];
    for (Eigen::Index j = 0; j <= i; ++j) {
      const Contact& cj = contacts[scratch.rows[j].contact];
      k(i, j) = k(j, i) =
          normal_coupling(ci, pi, cj, contacts.points(cj)[scratch.rows[j].point], inertia);
    }
    w0(i) = contact_normal_velocity(s, ci, pi) - pi.target_normal_velocity;
    start(i) = pi.normal_impulse;
  }
  return solve_normal_lcp(k, w0, start, scratch.lcp, scratch.impulse.head(n)).solved;
}

}  // namespace

int solve_small_islands(ContactSet& contacts, const BodyInertia& inertia, std::size_t max_points,
                        MotionState& s, IslandScratch& scratch) {
  if (contacts.empty() || max_points == 0) return 0;
  find_islands(contacts, inertia, scratch);
  const auto size = static_cast<Eigen::Index>(max_points);
  if (scratch.k.rows() < size) {
    scratch.k.resize(size, size);
    scratch.residual.resize(size);
    scratch.initial.resize(size);
    scratch.impulse.resize(size);
    scratch.rows.reserve(max_points);
    scratch.lcp.reserve(size);
  }
  int solved = 0;
  const std::size_t bodies = inertia.inverse_mass.size();
  for (std::size_t r = 0; r < bodies; ++r) {
    if (scratch.points[r] == 0 || scratch.points[r] > max_points) continue;
    scratch.rows.clear();
    for (std::uint32_t e = scratch.island_start[r]; e < scratch.cursor[r]; ++e) {
      for (int k = 0; k < contacts[scratch.order[e]].count(); ++k) {
        scratch.rows.push_back({scratch.order[e], static_cast<std::uint32_t>(k)});
      }
    }
    if (!solve_island(contacts, inertia, s, scratch)) continue;
    ++solved;
    for (std::size_t i = 0; i < scratch.rows.size(); ++i) {
      const Contact& c = contacts[scratch.rows[i].contact];
      ContactPointState& p = contacts.points(c)[scratch.rows[i].point];
      const double normal = scratch.impulse(static_cast<Eigen::Index>(i));
      const double limit = c.friction * normal;
      const double tangent = std::clamp(p.tangent_impulse, -limit, limit);
      apply_contact_impulse(c, p, normal - p.normal_impulse, tangent - p.tangent_impulse, inertia,
                            s);
      p.normal_impulse = normal;
      p.tangent_impulse = tangent;
    }
  }
  return solved;
}

}  // namespace gp
