#include "engine/solver/island_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/threads.hpp"

namespace gp {

// From this many columns, K's columns are counted and filled in side by side on the threads, a
// task per kColumnsPerTask: a column costs tens of nanoseconds (a 100-row pyramid's K has 600,000
// entries over 29,900 columns), and the first touch of its room a page fault of about 11 µs a
// 4 KiB page.
constexpr std::uint32_t kColumnsPerTask = 2048;
constexpr std::uint32_t kParallelColumns = 8192;

// Built in place, each column's entries where its count puts them: made from a list of entries
// (Eigen's setFromTriplets, which sorts a copy) it took 0.1 s of a 100-row pyramid's first solve
// of 0.3 s. The columns are counted first so that they can be filled in side by side.
void assemble_sparse(const ContactSet& contacts, const BodyInertia& inertia,
                     IslandScratch& scratch) {
  using End = IslandScratch::End;
  const auto n = static_cast<std::uint32_t>(scratch.rows.size());
  scratch.ends.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    const Contact& c = contacts[scratch.rows[i].contact];
    const ContactPointState& p = contacts.points(c)[scratch.rows[i].point];
    if (movable(inertia, c.body_a)) scratch.ends.push_back({c.body_a, i, 1.0, p.normal_arm_a});
    if (movable(inertia, c.body_b)) scratch.ends.push_back({c.body_b, i, -1.0, p.normal_arm_b});
  }
  std::sort(scratch.ends.begin(), scratch.ends.end(), [](const End& e, const End& f) {
    return e.body != f.body ? e.body < f.body : e.row < f.row;
  });
  const auto row_of = [](const End& e) { return e.row; };
  find_item_ends(scratch.ends, n, row_of, scratch.row_ends);
  // Entry (e.row, f.row) of the body of ends e and f, f being its column's.
  const auto share = [&](const End& e, const End& f) {
    const Vec2& n_e = contacts[scratch.rows[e.row].contact].normal;
    const Vec2& n_f = contacts[scratch.rows[f.row].contact].normal;
    return e.sign * f.sign *
           body_coupling(inertia.inverse_mass[e.body], inertia.inverse_moment[e.body], n_e.dot(n_f),
                         e.arm, f.arm);
  };
  SparseK& k = scratch.k_sparse;
  k.resize(n, n);
  int* const starts = k.outerIndexPtr();
  const bool alone = n < kParallelColumns;
  for_blocks(n, kColumnsPerTask, alone, [&](std::size_t first, std::size_t last) {
    for (std::size_t column = first; column < last; ++column) {
      const ItemEnds& row = scratch.row_ends[column];
      int count = 0;
      if (row.count > 0)
        for_each_coupled(scratch.ends, row, row_of, [&](auto, auto, auto) { ++count; });
      starts[column + 1] = count;
    }
  });
  for (std::uint32_t column = 0; column < n; ++column) starts[column + 1] += starts[column];
  k.resizeNonZeros(starts[n]);
  int* const inner = k.innerIndexPtr();
  double* const values = k.valuePtr();
  for_blocks(n, kColumnsPerTask, alone, [&](std::size_t first, std::size_t last) {
    for (std::size_t column = first; column < last; ++column) {
      const ItemEnds& row = scratch.row_ends[column];
      if (row.count == 0) continue;
      // The rows of the points on both of the column's bodies (its own, its contact's other
      // point) take a share from each; g is not read for a column of one body, whose second side
      // is empty.
      const End& f = scratch.ends[row.side[0].own];
      const End& g = scratch.ends[row.side[1].own];
      int at = starts[column];
      for_each_coupled(scratch.ends, row, row_of,
                       [&](std::uint32_t r, std::uint32_t on_f, std::uint32_t on_g) {
                         inner[at] = static_cast<int>(r);
                         if (on_g == kNoEnd) {
                           values[at] = share(scratch.ends[on_f], f);
                         } else if (on_f == kNoEnd) {
                           values[at] = share(scratch.ends[on_g], g);
                         } else {
                           values[at] = share(scratch.ends[on_f], f) + share(scratch.ends[on_g], g);
                         }
                         ++at;
                       });
    }
  });
}

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

// The normal impulses of the loaded island into scratch.impulse (solve_normal_lcp, as `options`
// say). Returns false where that finds none.
bool solve_island(const ContactSet& contacts, const BodyInertia& inertia,
                  const NormalLcpOptions& options, IslandScratch& scratch) {
  const auto n = static_cast<Eigen::Index>(scratch.rows.size());
  const auto w0 = scratch.residual.head(n);
  const auto start = scratch.initial.head(n);
  const auto impulse = scratch.impulse.head(n);
  if (n <= kDenseIslandPoints) {
    assemble_dense(contacts, inertia, scratch);
    return solve_normal_lcp(scratch.k_dense.topLeftCorner(n, n), w0, start, scratch.lcp, impulse,
                            options)
        .solved;
  }
  assemble_sparse(contacts, inertia, scratch);
  return solve_normal_lcp(scratch.k_sparse, w0, start, scratch.lcp, impulse, options).solved;
}

// Contacts of an island a task of its survey walks: a contact costs tens of nanoseconds, handing
// out a task about a microsecond.
constexpr std::size_t kSurveyContactsPerTask = 2048;

// Whether the survey of the island of `root` is shared out among the threads.
bool survey_on_threads(const ContactIslands& islands, std::size_t root) {
  return islands.island_end[root] - islands.island_start[root] >= 2 * kSurveyContactsPerTask;
}

// What one walk over an island's contacts finds, for reason_to_solve.
struct IslandSurvey {
  bool uneven;   // a dynamic body more than DirectSolveLimits::mass_ratio times as heavy as another
  bool at_rest;  // every movable body slower than the resting speeds at the start of the step,
                 // and no point deeper than the resting depth
  bool held;     // at rest: no point closing faster than DirectSolveLimits::unheld_speed now
};

// Whether the island of `root` is small enough for its uneven masses to let it in
// (Reason::kUneven).
bool may_be_uneven(const ContactIslands& islands, std::size_t root,
                   const DirectSolveLimits& limits) {
  return islands.points[root] <= limits.uneven_points;
}

// Whether `body` is not movable or slower than the resting speeds of `limits` in `start`.
bool resting_body(const BodyInertia& inertia, const MotionState& start,
                  const DirectSolveLimits& limits, BodyId body) {
  return !movable(inertia, body) ||
         (start.velocity[body].norm() < limits.resting_speed &&
          std::abs(start.angular_velocity[body]) < limits.resting_angular_speed);
}

// The bodies as the surveys read them: as solve_small_islands is given them, whether each rests
// (resting_body), and their state now.
struct SurveyedBodies {
  const IslandBodies& bodies;
  std::span<const std::uint8_t> resting;
  const MotionState& now;
};

IslandSurvey survey(const ContactSet& contacts, const ContactIslands& islands, std::size_t root,
                    const SurveyedBodies& surveyed, const DirectSolveLimits& limits) {
  const IslandBodies& bodies = surveyed.bodies;
  // The masses are compared only where an uneven island may be solved: a large resting pile's
  // survey runs at every step.
  const bool weigh = may_be_uneven(islands, root, limits);
  struct Found {
    double lightest = 0.0;  // as inverse masses [1/kg]
    double heaviest = std::numeric_limits<double>::infinity();
    bool at_rest = true;
    bool held = true;  // of every point walked: it counts only where the island is at rest
  };
  const std::uint32_t first = islands.island_start[root];
  const std::size_t count = islands.island_end[root] - first;
  const auto walk = [&](std::size_t from, std::size_t to, Found found) {
    // Whether the island is held counts only where it ends up at rest, and then every point was
    // walked at rest: each point's test is taken whatever the points before it found, without a
    // branch on them.
    for (std::size_t e = first + from; e < first + to; ++e) {
      // Neither at rest nor weighed: nothing further can change what the survey finds.
      if (!found.at_rest && !weigh) break;
      const Contact& c = contacts[islands.order[e]];
      found.at_rest &= (surveyed.resting[c.body_a] & surveyed.resting[c.body_b]) != 0;
      if (weigh) {
        for (const BodyId b : {c.body_a, c.body_b}) {
          const double inverse_mass = bodies.inertia.inverse_mass[b];
          if (inverse_mass > 0.0) {
            found.lightest = std::max(found.lightest, inverse_mass);
            found.heaviest = std::min(found.heaviest, inverse_mass);
          }
        }
      }
      for (const ContactPointState& p : contacts.points(c)) {
        // Bodies overlapping by more than the position passes leave are about to be moved apart:
        // impulses solved exactly for where they are would not fit where they go.
        found.at_rest &= p.depth <= limits.resting_depth;
        found.held &= contact_normal_velocity(surveyed.now, c, p) - p.target_normal_velocity >=
                      -limits.unheld_speed;
      }
    }
    return found;
  };
  // Every one of a resting pile's points is read at every step: a large pile's on the threads.
  const Found found = reduce_blocks(
      count, kSurveyContactsPerTask, !survey_on_threads(islands, root), Found{}, walk,
      [](const Found& x, const Found& y) {
        return Found{std::max(x.lightest, y.lightest), std::min(x.heaviest, y.heaviest),
                     x.at_rest && y.at_rest, x.held && y.held};
      });
  return {found.lightest > limits.mass_ratio * found.heaviest, found.at_rest, found.held};
}

// Frees the room a resting island's solve grew `scratch` to, keeping the dense islands' (and so
// their stride).
void release_large(IslandScratch& scratch) {
  // Moved-from temporaries take the room with them; `= {}` would keep a vector's capacity.
  scratch.rows = std::vector<IslandScratch::Row>();
  scratch.ends = std::vector<IslandScratch::End>();
  scratch.row_ends = std::vector<ItemEnds>();
  SparseK().swap(scratch.k_sparse);  // assigning an empty matrix would keep its entries' room
  scratch.residual = Eigen::VectorXd();
  scratch.initial = Eigen::VectorXd();
  scratch.impulse = Eigen::VectorXd();
  scratch.unloaded = std::vector<std::uint8_t>();
  scratch.ordered_contacts = std::vector<std::uint32_t>();
  scratch.order.release();
  scratch.lcp.release();
}

// Why an island is solved this step.
enum class Reason { kNone, kSmall, kUneven, kResting };

// Whether the island of `root` is surveyed (reason_to_solve): too large to be solved for its size
// alone, small enough to be solved for its uneven masses or at rest.
bool island_surveyed(const ContactIslands& islands, std::size_t root,
                     const DirectSolveLimits& limits) {
  const std::size_t points = islands.points[root];
  return points > limits.points &&
         (may_be_uneven(islands, root, limits) || points <= limits.resting_points);
}

// A resting island whose warm start holds it is left to the passes, which then settle it in a
// pass or two; a solve costs as much as hundreds of them. Where `settled` (surveys_settled), no
// island is surveyed.
Reason reason_to_solve(const ContactSet& contacts, const ContactIslands& islands, std::size_t root,
                       const SurveyedBodies& surveyed, const DirectSolveLimits& limits,
                       bool settled) {
  const std::size_t points = islands.points[root];
  if (points == 0) return Reason::kNone;
  if (points <= limits.points) return Reason::kSmall;
  if (settled || !island_surveyed(islands, root, limits)) return Reason::kNone;
  const bool uneven_allowed = may_be_uneven(islands, root, limits);
  const bool may_rest = points <= limits.resting_points;
  const IslandSurvey found = survey(contacts, islands, root, surveyed, limits);
  if (uneven_allowed && found.uneven) return Reason::kUneven;
  if (may_rest && found.at_rest && !found.held) return Reason::kResting;
  return Reason::kNone;
}

// The points of the island of `root` into scratch.rows: those of an island solved with a sparse
// K in an order whose factor stays sparse (island_contacts_in_order), the others in the
// contacts' own order.
void list_points(const ContactSet& contacts, const ContactIslands& islands, std::size_t root,
                 const BodyInertia& inertia, IslandScratch& scratch) {
  scratch.rows.clear();
  const auto list = [&](std::uint32_t contact) {
    for (int k = 0; k < contacts[contact].count(); ++k) {
      scratch.rows.push_back({contact, static_cast<std::uint32_t>(k)});
    }
  };
  if (islands.points[root] > kDenseIslandPoints) {
    island_contacts_in_order(contacts, islands, root, inertia, scratch.order,
                             scratch.ordered_contacts);
    for (const std::uint32_t contact : scratch.ordered_contacts) list(contact);
    return;
  }
  for (std::uint32_t e = islands.island_start[root]; e < islands.island_end[root]; ++e) {
    list(islands.order[e]);
  }
}

// Marks the points of scratch.rows of a resting island whose normals are square to `gravity`
// [m/s²], within a thousandth of a radian, in scratch.unloaded: gravity alone loads such an
// island, and not along them. Without gravity none is marked: nothing then tells which points a
// push from one side would load.
void mark_unloaded(const ContactSet& contacts, const Vec2& gravity, IslandScratch& scratch) {
  const double square = 1e-3 * gravity.norm();
  scratch.unloaded.clear();
  for (const IslandScratch::Row& row : scratch.rows) {
    const double along = contacts[row.contact].normal.dot(gravity);
    scratch.unloaded.push_back(square > 0.0 && std::abs(along) <= square ? 1 : 0);
  }
}

// Sets the targets of the points of scratch.rows to close every gap over the step h [s], however
// small. An island solved at every step meets them exactly: the passes' tolerance that counts a
// gap under a tenth of a micrometre as touching would leave a column resting on gaps of round-off
// (heavy_stack's top box 2e-8 m from the oracle's at 10 s, against 3e-9 m).
void close_gaps_exactly(ContactSet& contacts, const IslandScratch& scratch, double h) {
  for (const IslandScratch::Row& row : scratch.rows) {
    ContactPointState& p = contacts.points(contacts[row.contact])[row.point];
    p.target_normal_velocity = closing_target(p.depth, h, 0.0);
  }
}

// Solves the island of scratch.rows as `options` say and applies its impulses to `s`; returns
// whether it settled.
bool solve_listed_island(ContactSet& contacts, const BodyInertia& inertia,
                         const NormalLcpOptions& options, MotionState& s, IslandScratch& scratch) {
  if (scratch.k_dense.rows() == 0) {
    // One stride for every dense island, on every thread (NormalLcpScratch::reserve_dense).
    scratch.k_dense.resize(kDenseIslandPoints, kDenseIslandPoints);
    scratch.lcp.reserve_dense(kDenseIslandPoints);
  }
  load_island(contacts, s, scratch);
  if (!solve_island(contacts, inertia, options, scratch)) return false;
  for (std::size_t i = 0; i < scratch.rows.size(); ++i) {
    const Contact& c = contacts[scratch.rows[i].contact];
    ContactPointState& p = contacts.points(c)[scratch.rows[i].point];
    const double normal = scratch.impulse(static_cast<Eigen::Index>(i));
    const double limit = c.friction * normal;
    const double tangent = std::clamp(p.tangent_impulse, -limit, limit);
    apply_contact_impulse(c, p, normal - p.normal_impulse, tangent - p.tangent_impulse, inertia, s);
    p.normal_impulse = normal;
    p.tangent_impulse = tangent;
  }
  return true;
}

// What the islands of a range of roots came to.
struct Tally {
  int solved = 0;
  bool resting_failed = false;  // a resting island's solve did not settle
};

// A space of at least this many bodies has its islands solved side by side, a task per this many
// islands: a task costs about a microsecond to hand out, as much as a small island's solve or
// the survey of one of a hundred contacts.
constexpr std::size_t kParallelBodies = 4096;
constexpr std::size_t kIslandsPerTask = 8;
// Bodies a task tells at rest at a time: a body costs a nanosecond or two.
constexpr std::size_t kRestingBodiesPerTask = 8192;

}  // namespace

bool surveys_settled(const IslandBodies& bodies, const MotionState& now,
                     const DirectSolveLimits& limits) {
  struct Found {
    bool still = true;      // no point can close faster than a quarter of the unheld speed
    double lightest = 0.0;  // as inverse masses [1/kg]
    double heaviest = std::numeric_limits<double>::infinity();
  };
  const BodyInertia& inertia = bodies.inertia;
  const std::size_t count = inertia.inverse_mass.size();
  const Found found = reduce_blocks(
      count, kRestingBodiesPerTask, count < kParallelBodies, Found{},
      [&](std::size_t first, std::size_t last, Found f) {
        for (auto b = static_cast<BodyId>(first); b < last; ++b) {
          const double speed = now.velocity[b].norm();
          const double turning = std::abs(now.angular_velocity[b]);
          if (!movable(inertia, b)) {
            f.still &= speed == 0.0 && turning == 0.0;
            continue;
          }
          // A point's normal velocity is at most the sum of this over its two bodies, as its arm
          // crossed with the normal is at most contact_reach: twice the largest, half the unheld
          // speed, leaves room for the round-off of the survey's sums.
          f.still &= 4.0 * (speed + turning * bodies.contact_reach) <= limits.unheld_speed;
          const double inverse_mass = inertia.inverse_mass[b];
          if (inverse_mass > 0.0) {
            f.lightest = std::max(f.lightest, inverse_mass);
            f.heaviest = std::min(f.heaviest, inverse_mass);
          }
        }
        return f;
      },
      [](const Found& x, const Found& y) {
        return Found{x.still && y.still, std::max(x.lightest, y.lightest),
                     std::min(x.heaviest, y.heaviest)};
      });
  // An island's lightest is at most the space's, its heaviest at least the space's.
  return found.still && !(found.lightest > limits.mass_ratio * found.heaviest);
}

int solve_small_islands(ContactSet& contacts, const ContactIslands& islands,
                        const IslandBodies& bodies, const DirectSolveLimits& limits, MotionState& s,
                        DirectSolveScratch& scratch) {
  if (contacts.empty() || limits.points == 0) return 0;
  DirectSolveLimits active = limits;
  if (scratch.resting_pause > 0) {
    --scratch.resting_pause;
    active.resting_points = 0;
  }
  const std::size_t body_count = bodies.inertia.inverse_mass.size();
  const auto surveyed = [&](BodyId root) { return island_surveyed(islands, root, active); };
  // A body is in as many contacts as it touches shapes: told at rest once, rather than at each.
  scratch.resting.clear();
  const bool any_surveyed = std::any_of(islands.roots.begin(), islands.roots.end(), surveyed);
  // The bodies alone read, rather than every point of a resting pile at every step.
  const bool settled = any_surveyed && surveys_settled(bodies, s, active);
  if (any_surveyed && !settled) {
    scratch.resting.resize(body_count);
    for_blocks(body_count, kRestingBodiesPerTask, body_count < kParallelBodies,
               [&](std::size_t first, std::size_t last) {
                 for (auto b = static_cast<BodyId>(first); b < last; ++b) {
                   scratch.resting[b] = resting_body(bodies.inertia, bodies.start, active, b);
                 }
               });
  }
  const SurveyedBodies surveyed_bodies{bodies, scratch.resting, s};
  const auto solve_root = [&](BodyId r, IslandScratch& room, Tally& tally) {
    const Reason reason = reason_to_solve(contacts, islands, r, surveyed_bodies, active, settled);
    if (reason == Reason::kNone) return;
    list_points(contacts, islands, r, bodies.inertia, room);
    // An island let in by its uneven masses, which sequential impulses cannot hold up, is
    // worth more rounds than one they can.
    NormalLcpOptions options;
    if (reason == Reason::kUneven) options.max_rounds = kNormalLcpUnevenRounds;
    IslandAtRest at_rest;
    if (reason == Reason::kResting) {
      mark_unloaded(contacts, bodies.gravity, room);
      at_rest.unloaded = room.unloaded;
      options.at_rest = &at_rest;
    } else {
      close_gaps_exactly(contacts, room, bodies.h);
    }
    const bool settled = solve_listed_island(contacts, bodies.inertia, options, s, room);
    tally.solved += settled;
    if (reason == Reason::kResting) {
      // A resting island's solve comes once, not at every step: the room it grew to is freed.
      release_large(room);
      tally.resting_failed |= !settled;
    }
  };
  // An island whose survey the threads share is taken after the islands' loop, alone: from a task
  // of the loop, the survey's tasks would wait on the loop's others.
  const auto on_its_own = [&](BodyId root) {
    return !settled && surveyed(root) && survey_on_threads(islands, root);
  };
  const std::vector<BodyId>& roots = islands.roots;
  Tally tally = reduce_blocks(
      roots.size(), kIslandsPerTask, body_count < kParallelBodies, Tally{},
      [&](std::size_t first, std::size_t last, Tally part) {
        IslandScratch& room = scratch.per_thread.local();
        for (std::size_t k = first; k < last; ++k) {
          if (!on_its_own(roots[k])) solve_root(roots[k], room, part);
        }
        return part;
      },
      [](Tally a, Tally b) {
        return Tally{a.solved + b.solved, a.resting_failed || b.resting_failed};
      });
  for (const BodyId r : roots) {
    if (on_its_own(r)) solve_root(r, scratch.per_thread.local(), tally);
  }
  // One that does not settle would be tried again at every step, at up to 16 rounds of a large
  // factorisation each.
  if (tally.resting_failed) scratch.resting_pause = kRestingPauseSteps;
  return tally.solved;
}

}  // namespace gp
