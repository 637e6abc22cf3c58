#pragma once
// The linear complementarity problem of an island's normal impulses, solved exactly by block
// principal pivoting. Kept apart from the island's assembly (island_solver.hpp) so that it can
// be checked on problems whose solution is known.

#include <vector>

#include <Eigen/Dense>

namespace gp {

/// Scratch for solve_normal_lcp, kept by the caller so that a step does not allocate once it has
/// grown to the largest island.
struct NormalLcpScratch {
  Eigen::MatrixXd k_pushing;  // K restricted to the pushing points
  Eigen::VectorXd rhs;        // their right-hand side, then their impulse changes
  Eigen::VectorXd change;     // per point: Δλ of the current pushing set
  std::vector<char> pushing;  // per point: in the pushing set (w = 0) rather than free (λ = 0)
  std::vector<char> wrong;    // per point: on the wrong side of its complementarity condition
  std::vector<int> pushing_rows;

  /// Room for problems of up to `points` points.
  void reserve(Eigen::Index points);
};

/// How solve_normal_lcp ended.
struct NormalLcpResult {
  /// false: no solution within the round limit, a zero diagonal entry of K, or K restricted to
  /// a pushing set not positive definite in floating point
  bool solved;
  int rounds;  ///< pushing sets tried (each a Cholesky factorisation unless it is empty)
};

/// The most pushing sets the engine lets solve_normal_lcp try, each a Cholesky factorisation of
/// up to the island's size: the islands of the shipped scenes settle within 4 (rain1000) or 2
/// (heavy_stack, Newton's cradle). A heap of boxes piled through each other, where the points
/// ask for more than the bodies can give, may take hundreds, at up to 256³/3 flops a round; it
/// is left to the sequential impulses instead.
inline constexpr int kNormalLcpMaxRounds = 16;

/// Finds the normal impulses λ [N·s] of n contact points with
///   w = w₀ + K (λ − λ₀) ≥ 0,  λ ≥ 0,  λ · w = 0,
/// w [m/s] being each point's normal velocity less its target, w₀ the current one at the current
/// impulses λ₀ ≥ 0, and K [1/kg] the points' effective-mass matrix (symmetric, positive
/// semi-definite with a positive diagonal; GD:impulse's denominators on its diagonal). A
/// compliance of 1e-10 of each point's own diagonal entry, acting on λ − λ₀, makes K definite
/// where points are redundant, so that λ is unique: the conditions hold for K with it, to 1e-10
/// of the island's largest impulse and speed. (Where the points ask for more than the bodies can
/// give, λ is large and the compliance lets a point close by 1e-10 K_ii (λ_i − λ₀_i).) Writes
/// λ into `impulse` when solved. Block principal pivoting (Júdice and Pires) from the points
/// that pushed (λ₀ > 0) or are not moving apart (w₀ ≤ 0): all points on the wrong side change
/// sets at once while their number falls and for 3 rounds after it last fell, then one at a time
/// (Murty's rule, which cannot cycle for a definite K) until it falls below its best again; at
/// most `max_rounds` rounds.
NormalLcpResult solve_normal_lcp(const Eigen::Ref<const Eigen::MatrixXd>& k,
                                 const Eigen::Ref<const Eigen::VectorXd>& w0,
                                 const Eigen::Ref<const Eigen::VectorXd>& start,
                                 NormalLcpScratch& scratch, Eigen::Ref<Eigen::VectorXd> impulse,
                                 int max_rounds = kNormalLcpMaxRounds);

}  // namespace gp
