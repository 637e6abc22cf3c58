#include "engine/solver/island_solver.hpp"

#include <algorithm>

namespace gp {

namespace {

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

int solve_small_islands(ContactSet& contacts, const ContactIslands& islands,
                        const BodyInertia& inertia, std::size_t max_points, MotionState& s,
                        IslandScratch& scratch) {
  if (contacts.empty() || max_points == 0) return 0;
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
    if (islands.points[r] == 0 || islands.points[r] > max_points) continue;
    scratch.rows.clear();
    for (std::uint32_t e = islands.island_start[r]; e < islands.island_end[r]; ++e) {
      for (int k = 0; k < contacts[islands.order[e]].count(); ++k) {
        scratch.rows.push_back({islands.order[e], static_cast<std::uint32_t>(k)});
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
