#include "engine/solver/island_solver.hpp"

#include <algorithm>
#include <limits>

namespace gp {

namespace {

// K of the island of scratch.rows, dense, into scratch.k_dense: every entry, each from the bodies
// its two points share (normal_coupling).
void assemble_dense(const ContactSet& contacts, const BodyInertia& inertia,
                    IslandScratch& scratch) {
  const auto n = static_cast<Eigen::Index>(scratch.rows.size());
  auto k = scratch.k_dense.topLeftCorner(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Contact& ci = contacts[scratch.rows[i].contact];
    const ContactPointState& pi = contacts.points(ci)[scratch.rows[i].point];
    for (Eigen::Index j = 0; j <= i; ++j) {
      const Contact& cj = contacts[scratch.rows[j].contact];
      k(i, j) = k(j, i) =
          normal_coupling(ci, pi, cj, contacts.points(cj)[scratch.rows[j].point], inertia);
    }
  }
}

// K of the island of scratch.rows, sparse, into scratch.k_sparse: each movable body adds its share
// to the entries of every two points on it (body_coupling), so that K holds only what bodies
// share.
void assemble_sparse(const ContactSet& contacts, const BodyInertia& inertia,
                     IslandScratch& scratch) {
  scratch.ends.clear();
  for (std::uint32_t i = 0; i < scratch.rows.size(); ++i) {
    const Contact& c = contacts[scratch.rows[i].contact];
    const ContactPointState& p = contacts.points(c)[scratch.rows[i].point];
    if (movable(inertia, c.body_a)) scratch.ends.push_back({c.body_a, i, 1.0, p.normal_arm_a});
    if (movable(inertia, c.body_b)) scratch.ends.push_back({c.body_b, i, -1.0, p.normal_arm_b});
  }
  std::sort(scratch.ends.begin(), scratch.ends.end(),
            [](const IslandScratch::End& e, const IslandScratch::End& f) {
              return e.body != f.body ? e.body < f.body : e.row < f.row;
            });
  scratch.entries.clear();
  const auto normal = [&](const IslandScratch::End& e) -> const Vec2& {
    return contacts[scratch.rows[e.row].contact].normal;
  };
  for (auto first = scratch.ends.begin(); first != scratch.ends.end();) {
    const BodyId body = first->body;
    const auto last = std::find_if(first, scratch.ends.end(),
                                   [&](const IslandScratch::End& e) { return e.body != body; });
    for (auto e = first; e != last; ++e) {
      for (auto f = first; f != last; ++f) {
        scratch.entries.emplace_back(
            e->row, f->row,
            e->sign * f->sign *
                body_coupling(inertia.inverse_mass[body], inertia.inverse_moment[body],
                              normal(*e).dot(normal(*f)), e->arm, f->arm));
      }
    }
    first = last;
  }
  const auto n = static_cast<Eigen::Index>(scratch.rows.size());
  scratch.k_sparse.resize(n, n);
  scratch.k_sparse.setFromTriplets(scratch.entries.begin(), scratch.entries.end());
}

// Each point's w₀, its normal velocity less its target, and λ₀, its normal impulse, of the island
// of scratch.rows into scratch.residual and scratch.initial.
void load_island(const ContactSet& contacts, const MotionState& s, IslandScratch& scratch) {
  const auto n = static_cast<Eigen::Index>(scratch.rows.size());
  if (scratch.residual.size() < n) {
    scratch.residual.resize(n);
    scratch.initial.resize(n);
    scratch.impulse.resize(n);
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const Contact& c = contacts[scratch.rows[i].contact];
    const ContactPointState& p = contacts.points(c)[scratch.rows[i].point];
    scratch.residual(i) = contact_normal_velocity(s, c, p) - p.target_normal_velocity;
    scratch.initial(i) = p.normal_impulse;
  }
}

// Whether the carried-over impulses hold the island of `root` in `s`: no point closes faster
// than `unheld_speed` [m/s] (its normal velocity less its target).
bool held(const ContactSet& contacts, const ContactIslands& islands, std::size_t root,
          const MotionState& s, double unheld_speed) {
  for (std::uint32_t e = islands.island_start[root]; e < islands.island_end[root]; ++e) {
    const Contact& c = contacts[islands.order[e]];
    for (const ContactPointState& p : contacts.points(c)) {
      if (contact_normal_velocity(s, c, p) - p.target_normal_velocity < -unheld_speed) {
        return false;
      }
    }
  }
  return true;
}

// The normal impulses of the loaded island into scratch.impulse (solve_normal_lcp, in at most
// `max_rounds` rounds). Returns false where that finds none.
bool solve_island(const ContactSet& contacts, const BodyInertia& inertia, int max_rounds,
                  IslandScratch& scratch) {
  const auto n = static_cast<Eigen::Index>(scratch.rows.size());
  const auto w0 = scratch.residual.head(n);
  const auto start = scratch.initial.head(n);
  const auto impulse = scratch.impulse.head(n);
  if (n <= kDenseIslandPoints) {
    assemble_dense(contacts, inertia, scratch);
    return solve_normal_lcp(scratch.k_dense.topLeftCorner(n, n), w0, start, scratch.lcp, impulse,
                            max_rounds)
        .solved;
  }
  assemble_sparse(contacts, inertia, scratch);
  return solve_normal_lcp(scratch.k_sparse, w0, start, scratch.lcp, impulse, max_rounds).solved;
}

// Whether the island of `contacts` at `islands.order[first, last)` has a dynamic body more than
// `mass_ratio` times as heavy as another.
bool uneven(const ContactSet& contacts, const ContactIslands& islands, std::uint32_t first,
            std::uint32_t last, const BodyInertia& inertia, double mass_ratio) {
  double lightest = 0.0;  // as inverse masses [1/kg]
  double heaviest = std::numeric_limits<double>::infinity();
  for (std::uint32_t e = first; e < last; ++e) {
    const Contact& c = contacts[islands.order[e]];
    for (const BodyId b : {c.body_a, c.body_b}) {
      const double inverse_mass = inertia.inverse_mass[b];
      if (inverse_mass == 0.0) continue;
      lightest = std::max(lightest, inverse_mass);
      heaviest = std::min(heaviest, inverse_mass);
    }
  }
  return lightest > mass_ratio * heaviest;
}

// Whether every movable body of the island of `root` moved slower than `limits.resting_speed`
// and turned slower than `limits.resting_angular_speed` at the start of the step.
bool at_rest(const ContactSet& contacts, const ContactIslands& islands, std::size_t root,
             const IslandBodies& bodies, const DirectSolveLimits& limits) {
  for (std::uint32_t e = islands.island_start[root]; e < islands.island_end[root]; ++e) {
    const Contact& c = contacts[islands.order[e]];
    for (const BodyId b : {c.body_a, c.body_b}) {
      if (!movable(bodies.inertia, b)) continue;
      if (bodies.start.velocity[b].norm() >= limits.resting_speed ||
          std::abs(bodies.start.angular_velocity[b]) >= limits.resting_angular_speed) {
        return false;
      }
    }
  }
  return true;
}

// Frees the room a resting island's solve grew `scratch` to, keeping the dense islands' (and so
// their stride).
void release_large(IslandScratch& scratch) {
  // Moved-from temporaries take the room with them; `= {}` would keep a vector's capacity.
  scratch.rows = std::vector<IslandScratch::Row>();
  scratch.ends = std::vector<IslandScratch::End>();
  scratch.entries = std::vector<Eigen::Triplet<double>>();
  SparseK().swap(scratch.k_sparse);  // assigning an empty matrix would keep its entries' room
  scratch.residual = Eigen::VectorXd();
  scratch.initial = Eigen::VectorXd();
  scratch.impulse = Eigen::VectorXd();
  scratch.lcp.release();
}

// Why an island is solved this step.
enum class Reason { kNone, kSmall, kUneven, kResting };

Reason reason_to_solve(const ContactSet& contacts, const ContactIslands& islands, std::size_t root,
                       const IslandBodies& bodies, const DirectSolveLimits& limits) {
  const std::size_t points = islands.points[root];
  if (points == 0) return Reason::kNone;
  if (points <= limits.points) return Reason::kSmall;
  if (points <= limits.uneven_points &&
      uneven(contacts, islands, islands.island_start[root], islands.island_end[root],
             bodies.inertia, limits.mass_ratio)) {
    return Reason::kUneven;
  }
  if (points <= limits.resting_points && at_rest(contacts, islands, root, bodies, limits)) {
    return Reason::kResting;
  }
  return Reason::kNone;
}

}  // namespace

int solve_small_islands(ContactSet& contacts, const ContactIslands& islands,
                        const IslandBodies& bodies, const DirectSolveLimits& limits, MotionState& s,
                        IslandScratch& scratch) {
  const BodyInertia& inertia = bodies.inertia;
  if (contacts.empty() || limits.points == 0) return 0;
  if (scratch.k_dense.rows() == 0) {
    // One stride for every dense island (NormalLcpScratch::reserve_dense).
    scratch.k_dense.resize(kDenseIslandPoints, kDenseIslandPoints);
    scratch.lcp.reserve_dense(kDenseIslandPoints);
  }
  int solved = 0;
  const bool resting_paused = scratch.resting_pause > 0;
  if (resting_paused) --scratch.resting_pause;
  const std::size_t body_count = inertia.inverse_mass.size();
  for (std::size_t r = 0; r < body_count; ++r) {
    const Reason reason = reason_to_solve(contacts, islands, r, bodies, limits);
    if (reason == Reason::kNone || (reason == Reason::kResting && resting_paused)) continue;
    // A resting island whose warm start holds it is left to the passes, which then settle it in
    // a pass or two; a solve costs as much as hundreds of them.
    if (reason == Reason::kResting && held(contacts, islands, r, s, limits.unheld_speed)) continue;
    scratch.rows.clear();
    for (std::uint32_t e = islands.island_start[r]; e < islands.island_end[r]; ++e) {
      for (int k = 0; k < contacts[islands.order[e]].count(); ++k) {
        scratch.rows.push_back({islands.order[e], static_cast<std::uint32_t>(k)});
      }
    }
    load_island(contacts, s, scratch);
    // An island let in by its uneven masses, which sequential impulses cannot hold up, is worth
    // more rounds than one they can.
    const bool settled = solve_island(
        contacts, inertia, reason == Reason::kUneven ? kNormalLcpUnevenRounds : kNormalLcpMaxRounds,
        scratch);
    if (settled) {
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
    if (reason == Reason::kResting) {
      // A resting island's solve comes once, not at every step: the room it grew to is freed.
      // One that does not settle would be tried again at every step, at up to 16 rounds of a
      // large factorisation each.
      if (!settled) scratch.resting_pause = kRestingPauseSteps;
      release_large(scratch);
    }
  }
  return solved;
}

}  // namespace gp
