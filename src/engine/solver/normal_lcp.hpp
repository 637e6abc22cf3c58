#pragma once
// The linear complementarity problem of an island's normal impulses, solved exactly by block
// principal pivoting. Kept apart from the island's assembly (island_solver.hpp) so that it can
// be checked on problems whose solution is known.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace gp {

/// An island's effective-mass matrix K [1/kg], both triangles stored: a point couples only with
/// the points of its own two bodies, so a pile of hundreds of points has a few dozen entries a
/// row.
using SparseK = Eigen::SparseMatrix<double>;

/// What solve_normal_lcp keeps for a sparse K: the last factor of the solve, with the pushing set
/// it was made for. A later round whose pushing points are all among that set's, less a few that
/// let go, is solved with that factor, bordered by the rows of those few, rather than with a new
/// one: a pile's later rounds free tens of its tens of thousands of points.
struct SparseLcpScratch {
  SparseK k_pushing;  ///< K with its compliance, restricted to the factored pushing set
  Eigen::SimplicialLLT<SparseK, Eigen::Lower, Eigen::NaturalOrdering<int>> factor;
  std::vector<int> factored_points;         ///< per row of `factor`: its point
  std::vector<int> let_go;                  ///< rows of `factor` whose points no longer push
  SparseK border;                           ///< L⁻¹ times the identity's columns of those rows
  Eigen::MatrixXd gram;                     ///< its Gram matrix (lower triangle), those rows'
                                            ///< block of the factored matrix's inverse
  Eigen::LLT<Eigen::MatrixXd> gram_factor;  ///< of `gram`
  Eigen::VectorXd target;                   ///< the right-hand side over the rows of `factor`
  /// A column over the rows of `factor`: each column of W as it is solved, then what a bordered
  /// solve leaves of `target`.
  Eigen::VectorXd column;
};

/// Scratch for solve_normal_lcp, kept by the caller so that a step reuses the room of the last.
struct NormalLcpScratch {
  Eigen::VectorXd diagonal;       // per point: K_ii
  Eigen::VectorXd change;         // per point: Δλ of the current pushing set
  Eigen::VectorXd speed;          // per point: w after `change`
  Eigen::VectorXd rhs;            // the pushing points' right-hand side, then their Δλ
  std::vector<char> pushing;      // per point: in the pushing set (w = 0) rather than free (λ = 0)
  std::vector<char> wrong;        // per point: on the wrong side of its complementarity condition
  std::vector<int> pushing_row;   // per point: its row among the pushing points, or −1
  std::vector<int> pushing_rows;  // the pushing points, ascending
  // K with its compliance, restricted to the pushing points, of a dense K.
  Eigen::MatrixXd k_pushing_dense;
  /// Of a sparse K, made at its first solve; release_sparse() frees it.
  std::unique_ptr<SparseLcpScratch> sparse;

  /// Room for problems of up to `points` points.
  void reserve(Eigen::Index points);
  /// Room for the pushing sets of dense problems of up to `points` points. Their factorisation's
  /// rounding depends on the room's stride (Eigen vectorises by alignment), so that the engine
  /// keeps one stride for every island.
  void reserve_dense(Eigen::Index points);
  /// Frees the room for large problems, tens of megabytes after a pile of 30,000 points, keeping
  /// that of the dense pushing sets (and so its stride).
  void release();
};

/// How solve_normal_lcp ended.
struct NormalLcpResult {
  /// false: no solution within the round limit, a zero diagonal entry of K, or K restricted to
  /// a pushing set not positive definite in floating point
  bool solved;
  int rounds;  ///< pushing sets tried
  /// Cholesky factorisations made: one a round, but for empty pushing sets and the rounds of a
  /// sparse K that border the last factor (NormalLcpOptions::most_let_go).
  int factorisations = 0;
};

/// The most pushing sets the engine lets solve_normal_lcp try, each a Cholesky factorisation of
/// up to the island's size: the islands of the shipped scenes settle within 4 (rain1000) or 2
/// (heavy_stack, Newton's cradle). A heap of boxes piled through each other, where the points
/// ask for more than the bodies can give, may take hundreds; it is left to the sequential
/// impulses instead, which push it apart more gently.
inline constexpr int kNormalLcpMaxRounds = 16;
/// The same for an island of uneven masses, which the sequential impulses cannot hold up: a
/// pyramid of 55 boxes under a box 300 times denser (292 points) settles within 64 rounds at all
/// but 15 of its 600 steps.
inline constexpr int kNormalLcpUnevenRounds = 64;

/// What solve_normal_lcp may take for granted of an island at rest (its bodies slow, no point
/// overlapping by more than the slop): its points ask for no more than the bodies can give, and
/// gravity alone loads them.
struct IslandAtRest {
  /// One flag per point: no applied force presses along its normal, as along the sides of a
  /// pile's boxes under gravity. Such a point carries next to nothing.
  std::span<const std::uint8_t> unloaded;
};

/// The most points of the last factored pushing set of a sparse K that may have let go for a
/// round to border that factor rather than make a new one: bordering costs a sparse triangular
/// solve for each, and 70 of them a quarter of a new factor of a 100-row pyramid's 20,000 pushing
/// points.
inline constexpr std::size_t kNormalLcpMostLetGo = 128;

/// How solve_normal_lcp goes about a problem.
struct NormalLcpOptions {
  int max_rounds = kNormalLcpMaxRounds;   ///< the most pushing sets it tries
  const IslandAtRest* at_rest = nullptr;  ///< set for an island at rest (see solve_normal_lcp)
  /// Of a sparse K: the most let-go points a factor is bordered with (0: a new factor a round).
  std::size_t most_let_go = kNormalLcpMostLetGo;
};

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
/// most `options.max_rounds` rounds.
///
/// Of an island `options.at_rest`: the points it marks unloaded start free unless closing (starting
/// them pushing would cost a round of every point, to let them go), and a free point may close as
/// fast as the compliance lets a pushing one (round by round, the speed scale takes in each
/// K_ii |λ_i − λ₀_i|, of which the compliance's speed is 1e-10): a pile's impulses reach its whole
/// weight, and the compliance's speeds with them, while its w₀ is a step of gravity, so that
/// measured against w₀ alone the last rounds chase the compliance's speeds (7 rounds of a 40-row
/// pyramid instead of 3).
NormalLcpResult solve_normal_lcp(const Eigen::Ref<const Eigen::MatrixXd>& k,
                                 const Eigen::Ref<const Eigen::VectorXd>& w0,
                                 const Eigen::Ref<const Eigen::VectorXd>& start,
                                 NormalLcpScratch& scratch, Eigen::Ref<Eigen::VectorXd> impulse,
                                 const NormalLcpOptions& options = {});
/// The same for a sparse K, each round's pushing set in K's own order, which had better keep the
/// factor sparse (island_contacts_in_order gives one): for the large islands, where a round of
/// the dense solve would cost the cube of their points. A round that
/// only lets a few points go (`options.most_let_go`) borders the last factor with their rows
/// instead of making a new one, to the same solution up to round-off.
NormalLcpResult solve_normal_lcp(const SparseK& k, const Eigen::Ref<const Eigen::VectorXd>& w0,
                                 const Eigen::Ref<const Eigen::VectorXd>& start,
                                 NormalLcpScratch& scratch, Eigen::Ref<Eigen::VectorXd> impulse,
                                 const NormalLcpOptions& options = {});

}  // namespace gp
