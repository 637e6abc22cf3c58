#pragma once
// The normal impulses of a small island of contacts solved exactly, all at once. Sequential
// impulses converge slowly where a light body carries a heavy one: a column of ten boxes whose
// density grows a hundredfold to the top still sinks and leans after 160 passes a step. The exact
// solution of the island's linear complementarity problem has no such limit, and for an island
// of a few dozen points costs less than those passes.

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "engine/solver/contact_islands.hpp"
#include "engine/solver/normal_lcp.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace gp {

/// Scratch for solve_small_islands, kept by the caller so that a step does not allocate once it
/// has grown to the scene.
struct IslandScratch {
  struct Row {
    std::uint32_t contact;
    std::uint32_t point;
  };
  std::vector<Row> rows;     // the island's points
  Eigen::MatrixXd k;         // 1/kg: effective-mass matrix of the island's points
  Eigen::VectorXd residual;  // m/s: w₀, each point's normal velocity less its target
  Eigen::VectorXd initial;   // N·s: λ₀, each point's normal impulse so far
  Eigen::VectorXd impulse;   // N·s: λ, the solution
  NormalLcpScratch lcp;
};

/// For each of the `islands` of `contacts` (contacts joined through the dynamic bodies they share)
/// of at most `max_points` contact points, sets the points' normal impulses λ to the solution of
///   w = w₀ + K (λ − λ₀) ≥ 0,  λ ≥ 0,  λ · w = 0
/// where w is each point's normal velocity less its target, w₀ and λ₀ the current ones, and K
/// the effective-mass matrix of the points (GD:impulse's denominators on its diagonal), with the
/// friction impulses held; then clamps the friction impulses to the new friction cones. Found by
/// solve_normal_lcp; an island it does not solve (within its round limit, or with K on a
/// pushing set not positive definite) keeps its impulses for the sequential passes. Applies the
/// changes to the velocities of `s` (DD:impulseV, DD:torque, TM:NewtonThirdLawMot). Returns the
/// number of islands solved.
int solve_small_islands(ContactSet& contacts, const ContactIslands& islands,
                        const BodyInertia& inertia, std::size_t max_points, MotionState& s,
                        IslandScratch& scratch);

}  // namespace gp
