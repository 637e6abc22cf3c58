#pragma once
// The normal impulses of a small island of contacts solved exactly, all at once. Sequential
// impulses converge slowly where a light body carries a heavy one: a column of ten boxes whose
// density grows a hundredfold to the top still sinks and leans after 160 passes a step. The exact
// solution of the island's linear complementarity problem has no such limit, and for an island
// of a few dozen points costs less than those passes.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "engine/solver/contact_islands.hpp"
#include "engine/solver/coupled_items.hpp"
#include "engine/solver/island_order.hpp"
#include "engine/solver/normal_lcp.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace gp {

/// Islands of up to this many points take a dense K, solved without allocating once the scratch
/// has grown; larger ones a sparse K, which allocates as Eigen's sparse Cholesky does: a dense
/// round costs the cube of the points, 8 Mflop at 292.
inline constexpr Eigen::Index kDenseIslandPoints = 64;

/// The room of one island's solve, one per thread.
struct IslandScratch {
  struct Row {
    std::uint32_t contact;
    std::uint32_t point;
  };
  // A point's end on one of its movable bodies: its place in K's rows, and its sign (A +, B −)
  // and arm crossed with the normal [m] there.
  struct End {
    BodyId body;
    std::uint32_t row;
    double sign;
    double arm;
  };
  std::vector<Row> rows;  // the island's points
  // Of an island solved with a sparse K: its contacts in the order its points are listed in.
  std::vector<std::uint32_t> ordered_contacts;
  IslandOrderScratch order;
  // 1/kg: effective-mass matrix of the island's points, dense for an island of at most
  // kDenseIslandPoints, else sparse (from its entries, body by body).
  Eigen::MatrixXd k_dense;
  std::vector<End> ends;           // the points' ends, by body
  std::vector<ItemEnds> row_ends;  // per point: its ends, by body
  SparseK k_sparse;
  Eigen::VectorXd residual;  // m/s: w₀, each point's normal velocity less its target
  Eigen::VectorXd initial;   // N·s: λ₀, each point's normal impulse so far
  Eigen::VectorXd impulse;   // N·s: λ, the solution
  // Of an island at rest, per point: no gravity along its normal (IslandAtRest::unloaded).
  std::vector<std::uint8_t> unloaded;
  NormalLcpScratch lcp;
};

/// K, the effective-mass matrix of the island of scratch.rows, sparse, into scratch.k_sparse
/// [1/kg]: each movable body adds its share to the entries of every two points on it
/// (body_coupling), so that K holds only what bodies share; normal_coupling gives each entry alone.
/// For islands of more than kDenseIslandPoints points.
void assemble_sparse(const ContactSet& contacts, const BodyInertia& inertia,
                     IslandScratch& scratch);

/// Scratch for solve_small_islands, kept by the caller so that a step reuses the room of the
/// last.
struct DirectSolveScratch {
  tbb::enumerable_thread_specific<IslandScratch> per_thread;
  // Per body, of a step whose islands are surveyed: 1 where it is slower than the resting speeds
  // at the start of the step or not movable, else 0.
  std::vector<std::uint8_t> resting;
  // Calls of solve_small_islands left in which no resting island is solved, after a resting
  // island's solve did not settle.
  int resting_pause = 0;
};

/// Calls of solve_small_islands (steps or sub-steps) that a resting island's solve that does not
/// settle pauses the solve of resting islands for: such a solve costs up to 16 factorisations of
/// its island (2 s for a 100-row pyramid), and paused it takes at most one call in 64.
inline constexpr int kRestingPauseSteps = 64;

/// Which islands solve_small_islands solves: those of at most `points` contact points; those of
/// at most `uneven_points` whose heaviest dynamic body is more than `mass_ratio` times as heavy
/// as their lightest; and those of at most `resting_points` at rest (every body slower than
/// `resting_speed` and `resting_angular_speed` at the start of the step, and no point overlapping
/// by more than `resting_depth`) whose warm start does not hold them (a point closing faster than
/// `unheld_speed` after it). None when `points` is 0.
/// (Settings::direct_solve_points, direct_solve_uneven_points, direct_solve_mass_ratio,
/// direct_solve_resting_points.)
struct DirectSolveLimits {
  std::size_t points;
  std::size_t uneven_points;
  double mass_ratio;
  std::size_t resting_points;
  double resting_speed;          ///< m/s
  double resting_angular_speed;  ///< rad/s
  double unheld_speed;           ///< m/s
  double resting_depth;          ///< m
};

/// The bodies as solve_small_islands reads them: their inertias, their motion at the start of the
/// step, the step's length, and the gravity they fall in.
struct IslandBodies {
  const BodyInertia& inertia;
  const MotionState& start;
  double h;      ///< s
  Vec2 gravity;  ///< m/s²
  /// m: the farthest a contact point of a movable body in an island at rest lies from its centre
  /// of mass, at least (BodyShapes::moving_reach, and the contact margin or the slop).
  double contact_reach;
};

/// Whether the bodies alone tell that no island solve_small_islands surveys is to be solved, so
/// that the surveys, which read every point, can be skipped: every body not movable is still, and
/// every movable one so slow in `now` that no point of it can close faster than a quarter of
/// `limits.unheld_speed` (|v| + |ω| · contact_reach, for each of a point's two bodies; a point's
/// target is never positive), and no dynamic body is more than `limits.mass_ratio` times as heavy
/// as another. A resting pile's warm start leaves its bodies many orders of magnitude slower.
bool surveys_settled(const IslandBodies& bodies, const MotionState& now,
                     const DirectSolveLimits& limits);

/// For each of the `islands` of `contacts` (contacts joined through the dynamic bodies they share)
/// within `limits`, sets the points' normal impulses λ to the solution of
///   w = w₀ + K (λ − λ₀) ≥ 0,  λ ≥ 0,  λ · w = 0
/// where w is each point's normal velocity less its target, w₀ and λ₀ the current ones, and K
/// the effective-mass matrix of the points (GD:impulse's denominators on its diagonal), with the
/// friction impulses held; then clamps the friction impulses to the new friction cones. An island
/// solved for its size or its uneven masses closes every gap over the step (closing_target with
/// no touching gap), as the passes then do too. Found by
/// solve_normal_lcp; an island it does not solve (within its round limit, or with K on a
/// pushing set not positive definite) keeps its impulses for the sequential passes. Applies the
/// changes to the velocities of `s` (DD:impulseV, DD:torque, TM:NewtonThirdLawMot). The islands
/// are solved side by side on the threads of the current task arena, each alone, so that the
/// result does not depend on their number. Returns the number of islands solved.
int solve_small_islands(ContactSet& contacts, const ContactIslands& islands,
                        const IslandBodies& bodies, const DirectSolveLimits& limits, MotionState& s,
                        DirectSolveScratch& scratch);

}  // namespace gp
