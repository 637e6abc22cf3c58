#include "engine/solver/normal_lcp.hpp"

#include <algorithm>
#include <cmath>

namespace gp {

namespace {

// Rounds in which every point on the wrong side changes set although their number did not fall.
constexpr int kBlockRounds = 3;
// The compliance, relative to each point's own entry of K, that makes K definite.
constexpr double kCompliance = 1e-10;
// Relative error accepted in the impulses and speeds: the compliance bounds K's condition number
// near 1e10, so a solve is good to about 1e-6 in the worst case, and far better in most.
constexpr double kRoundOff = 1e-10;
// A floor for the scales of impulses [N·s] and speeds [m/s], so that an island at rest still has
// a (normal, not subnormal) tolerance.
constexpr double kTiny = 1e-200;

// How a round's pushing set was solved.
struct RoundSolve {
  bool solved;    // false: K restricted to the pushing points is not positive definite
  bool factored;  // with a new factorisation
};

// Point i's speed w_i = w₀_i + (K + compliance) Δλ after the impulse changes `change` [m/s]: the
// one problem, K with its compliance, that every round works on (on which Murty's rule cannot
// cycle). A dense K, row by row: only the rows a round needs.
double speed_after(const Eigen::Ref<const Eigen::MatrixXd>& k,
                   const Eigen::Ref<const Eigen::VectorXd>& w0,
                   const Eigen::Ref<const Eigen::VectorXd>& change, Eigen::Index i) {
  return w0(i) + k.row(i).dot(change) + kCompliance * k(i, i) * change(i);
}

// The same for every point of a sparse K, into scratch.speed.
void speeds_after_change(const SparseK& k, const Eigen::Ref<const Eigen::VectorXd>& w0,
                         NormalLcpScratch& scratch) {
  const Eigen::Index n = k.rows();
  auto speed = scratch.speed.head(n);
  const auto change = scratch.change.head(n);
  speed.noalias() = k * change;
  speed += w0 + kCompliance * scratch.diagonal.head(n).cwiseProduct(change);
}

// Readies `scratch` for the rounds of a problem of a sparse K: the factor of the last problem
// serves none of them. K's points come in an order whose factor stays sparse
// (island_contacts_in_order), which every round's pushing points keep.
void start_rounds(const SparseK&, NormalLcpScratch& scratch) {
  if (!scratch.sparse) scratch.sparse = std::make_unique<SparseLcpScratch>();
  scratch.sparse->factored_points.clear();
}

// A dense K's need nothing.
void start_rounds(const Eigen::Ref<const Eigen::MatrixXd>&, NormalLcpScratch&) {}

// The pushing points' changes Δλ (unknown, set to 0) and the free points' (−λ₀) into
// scratch.change, and the pushing points, ascending, into scratch.pushing_rows, each point's row
// among them into scratch.pushing_row (−1: free).
void list_pushing(const Eigen::Ref<const Eigen::VectorXd>& start, NormalLcpScratch& scratch) {
  scratch.pushing_rows.clear();
  for (Eigen::Index point = 0; point < start.size(); ++point) {
    const auto i = static_cast<std::size_t>(point);
    scratch.pushing_row[i] = -1;
    if (scratch.pushing[i]) {
      scratch.pushing_row[i] = static_cast<int>(scratch.pushing_rows.size());
      scratch.pushing_rows.push_back(static_cast<int>(point));
    }
    scratch.change(point) = scratch.pushing[i] ? 0.0 : -start(point);
  }
}

// The pushing points' Δλ, so that they push (w = 0) while the free ones let go (λ = 0), into
// scratch.change, and the free points' speeds after it into scratch.speed, for a dense K.
RoundSolve solve_listed(const Eigen::Ref<const Eigen::MatrixXd>& k,
                        const Eigen::Ref<const Eigen::VectorXd>& w0, const NormalLcpOptions&,
                        NormalLcpScratch& scratch) {
  const Eigen::Index n = k.rows();
  auto change = scratch.change.head(n);
  const auto a = static_cast<Eigen::Index>(scratch.pushing_rows.size());
  if (a > 0) {
    scratch.reserve_dense(n);
    auto k_pushing = scratch.k_pushing_dense.topLeftCorner(a, a);
    auto rhs = scratch.rhs.head(a);
    for (Eigen::Index r = 0; r < a; ++r) {
      const int i = scratch.pushing_rows[r];
      // The speed the free points' letting go leaves; the pushing points' changes, still 0 in
      // `change`, are the unknowns.
      rhs(r) = -speed_after(k, w0, change, i);
      for (Eigen::Index q = 0; q < a; ++q) k_pushing(r, q) = k(i, scratch.pushing_rows[q]);
      // A heap is often statically indeterminate (a box across two others: more points than
      // the bodies' vertical and turning freedoms), which makes K singular.
      k_pushing(r, r) *= 1.0 + kCompliance;
    }
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> factor(k_pushing);
    if (factor.info() != Eigen::Success) return {false, true};
    factor.solveInPlace(rhs);
    for (Eigen::Index r = 0; r < a; ++r) change(scratch.pushing_rows[r]) = rhs(r);
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!scratch.pushing[i]) scratch.speed(i) = speed_after(k, w0, change, i);
  }
  return {true, a > 0};
}

// Factors K with its compliance restricted to the pushing points, rows in K's order, into
// sparse.factor, and makes them the factored set. Returns false if it is not positive definite.
bool factor_pushing(const SparseK& k, NormalLcpScratch& scratch) {
  SparseLcpScratch& sparse = *scratch.sparse;
  const auto a = static_cast<Eigen::Index>(scratch.pushing_rows.size());
  SparseK& k_pushing = sparse.k_pushing;
  k_pushing.resize(a, a);
  k_pushing.reserve(k.nonZeros());
  for (Eigen::Index q = 0; q < a; ++q) {
    k_pushing.startVec(q);
    for (SparseK::InnerIterator entry(k, scratch.pushing_rows[q]); entry; ++entry) {
      const int r = scratch.pushing_row[static_cast<std::size_t>(entry.row())];
      if (r < 0) continue;
      k_pushing.insertBack(r, q) = r == q ? entry.value() * (1.0 + kCompliance) : entry.value();
    }
  }
  k_pushing.finalize();
  sparse.factor.compute(k_pushing);
  sparse.factored_points = scratch.pushing_rows;
  sparse.let_go.clear();
  return sparse.factor.info() == Eigen::Success;
}

// Whether the factored set still serves the pushing points: each of them is in it, and at most
// `most_let_go` of its points have let go since (into sparse.let_go, as its rows).
bool factor_serves(std::size_t most_let_go, NormalLcpScratch& scratch) {
  SparseLcpScratch& sparse = *scratch.sparse;
  if (sparse.factored_points.empty()) return false;
  sparse.let_go.clear();
  for (std::size_t row = 0; row < sparse.factored_points.size(); ++row) {
    const int i = sparse.factored_points[row];
    if (scratch.pushing[i]) continue;
    if (sparse.let_go.size() == most_let_go) return false;
    sparse.let_go.push_back(static_cast<int>(row));
  }
  // The factored points still pushing are all the pushing points only if they are as many.
  return sparse.factored_points.size() - sparse.let_go.size() == scratch.pushing_rows.size();
}

// W = L⁻¹ E into sparse.border, L Lᵀ being the factored matrix and E the identity's columns of
// the let-go rows, and the Cholesky factor of WᵀW, their block of the factored matrix's inverse.
// Returns false if WᵀW is not positive definite in floating point.
bool border(SparseLcpScratch& sparse) {
  const auto rows = static_cast<Eigen::Index>(sparse.factored_points.size());
  SparseK& w = sparse.border;
  w.resize(rows, static_cast<Eigen::Index>(sparse.let_go.size()));
  // Column by column through one dense column, whose solve skips its zeros: W holds a few hundred
  // entries a column, the let-go row's path to the root of the factor's elimination tree.
  Eigen::VectorXd& column = sparse.column;
  column.setZero(rows);
  for (std::size_t q = 0; q < sparse.let_go.size(); ++q) {
    column(sparse.let_go[q]) = 1.0;
    sparse.factor.matrixL().solveInPlace(column);
    w.startVec(static_cast<Eigen::Index>(q));
    for (Eigen::Index row = sparse.let_go[q]; row < rows; ++row) {
      if (column(row) == 0.0) continue;
      w.insertBack(row, static_cast<Eigen::Index>(q)) = column(row);
      column(row) = 0.0;
    }
  }
  w.finalize();
  // WᵀW by the columns' dot products, each a merge of two paths: Eigen's sparse product of the
  // two takes twice as long.
  const Eigen::Index let_go = w.cols();
  Eigen::MatrixXd& gram = sparse.gram;
  gram.resize(let_go, let_go);
  for (Eigen::Index j = 0; j < let_go; ++j) {
    for (Eigen::Index q = j; q < let_go; ++q) gram(q, j) = w.col(q).dot(w.col(j));
  }
  sparse.gram_factor.compute(gram);
  return sparse.gram_factor.info() == Eigen::Success;
}

// Solves A z = b in place on the rows of the factored matrix A = L Lᵀ other than the let-go ones,
// where z = 0 instead: z = L⁻ᵀ (u + W y), with u = L⁻¹ b and y = −(WᵀW)⁻¹ Wᵀ u, so that
// Eᵀz = Wᵀ(u + W y) = 0 and A z = b + E y.
void solve_bordered(SparseLcpScratch& sparse, Eigen::Ref<Eigen::VectorXd> z) {
  sparse.factor.matrixL().solveInPlace(z);
  const SparseK& w = sparse.border;
  z -= w * sparse.gram_factor.solve(w.transpose() * z);
  sparse.factor.matrixU().solveInPlace(z);
  for (const int row : sparse.let_go) z(row) = 0.0;
}

// The pushing points' Δλ and every point's speed after it, as for a dense K, from the factored
// set's factor: made anew unless it still serves (factor_serves), in which case the let-go
// points' rows border it, and one round of refinement takes back what the bordering loses to
// round-off (it cancels entries of K⁻¹ as large as the compliance makes them).
RoundSolve solve_listed(const SparseK& k, const Eigen::Ref<const Eigen::VectorXd>& w0,
                        const NormalLcpOptions& options, NormalLcpScratch& scratch) {
  speeds_after_change(k, w0, scratch);
  if (scratch.pushing_rows.empty()) return {true, false};
  const bool bordered = factor_serves(options.most_let_go, scratch) && border(*scratch.sparse);
  if (!bordered && !factor_pushing(k, scratch)) return {false, true};
  SparseLcpScratch& sparse = *scratch.sparse;
  const auto rows = static_cast<Eigen::Index>(sparse.factored_points.size());
  const auto point_of = [&](Eigen::Index row) {
    return sparse.factored_points[static_cast<std::size_t>(row)];
  };
  // The speed the free points' letting go leaves, to be undone by the pushing points.
  Eigen::VectorXd& target = sparse.target;
  target.resize(rows);
  for (Eigen::Index row = 0; row < rows; ++row) {
    const int i = point_of(row);
    target(row) = scratch.pushing[i] ? -scratch.speed(i) : 0.0;
  }
  auto rhs = scratch.rhs.head(rows);
  if (bordered) {
    rhs = target;
    solve_bordered(sparse, rhs);
    Eigen::VectorXd& residual = sparse.column;
    residual.noalias() = target - sparse.k_pushing * rhs;
    for (const int row : sparse.let_go) residual(row) = 0.0;
    solve_bordered(sparse, residual);
    rhs += residual;
  } else {
    rhs = sparse.factor.solve(target);
  }
  for (Eigen::Index row = 0; row < rows; ++row) {
    const int i = point_of(row);
    if (scratch.pushing[i]) scratch.change(i) = rhs(row);
  }
  speeds_after_change(k, w0, scratch);
  return {true, !bordered};
}

template <typename Matrix>
NormalLcpResult solve_lcp(const Matrix& k, const Eigen::Ref<const Eigen::VectorXd>& w0,
                          const Eigen::Ref<const Eigen::VectorXd>& start, NormalLcpScratch& scratch,
                          Eigen::Ref<Eigen::VectorXd> impulse, const NormalLcpOptions& options) {
  const IslandAtRest* const at_rest = options.at_rest;
  const Eigen::Index n = k.rows();
  scratch.reserve(n);
  const auto change = scratch.change.head(n);
  // One scale for the whole island: the largest impulse at stake (the largest so far, and the
  // largest that alone would stop a closing point) and the largest speed (w₀, and what the
  // compliance adds to it).
  double impulse_scale = kTiny;
  double speed_scale = kTiny;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double k_ii = scratch.diagonal(i) = k.coeff(i, i);
    if (!(k_ii > 0.0)) return {false, 0};  // a point no body can move: no solution
    impulse_scale = std::max(impulse_scale, start(i) + std::max(-w0(i) / k_ii, 0.0));
    speed_scale = std::max(speed_scale, std::abs(w0(i)) + kCompliance * k_ii * start(i));
  }
  start_rounds(k, scratch);
  const double impulse_tolerance = kRoundOff * impulse_scale;
  double speed_tolerance = kRoundOff * speed_scale;
  // A stack starting at rest pushes at every level, not only where gravity has already made the
  // points close.
  for (Eigen::Index i = 0; i < n; ++i) {
    const bool unloaded = at_rest != nullptr && at_rest->unloaded[i] != 0;
    scratch.pushing[i] =
        start(i) > 0.0 || w0(i) < -speed_tolerance || (w0(i) <= speed_tolerance && !unloaded);
  }
  Eigen::Index fewest_wrong = n + 1;
  int block_rounds_left = 0;
  int factorisations = 0;
  for (int round = 1; round <= options.max_rounds; ++round) {
    list_pushing(start, scratch);
    const RoundSolve solve = solve_listed(k, w0, options, scratch);
    factorisations += solve.factored;
    if (!solve.solved) return {false, round, factorisations};
    if (at_rest != nullptr) {
      for (Eigen::Index i = 0; i < n; ++i) {
        speed_scale = std::max(speed_scale, scratch.diagonal(i) * std::abs(change(i)));
      }
      speed_tolerance = kRoundOff * speed_scale;
    }
    Eigen::Index wrong = 0;
    Eigen::Index last_wrong = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      scratch.wrong[i] = scratch.pushing[i] ? start(i) + change(i) < -impulse_tolerance
                                            : scratch.speed(i) < -speed_tolerance;
      if (scratch.wrong[i]) {
        ++wrong;
        last_wrong = i;
      }
    }
    if (wrong == 0) {
      impulse = (start + change).cwiseMax(0.0);
      return {true, round, factorisations};
    }
    if (wrong < fewest_wrong) {
      fewest_wrong = wrong;
      block_rounds_left = kBlockRounds + 1;  // this round, and kBlockRounds more
    }
    if (block_rounds_left > 0) {
      --block_rounds_left;
      for (Eigen::Index i = 0; i < n; ++i) scratch.pushing[i] ^= scratch.wrong[i];
    } else {
      // Murty's rule needs one fixed order of the points to choose by: the last wrong one.
      scratch.pushing[last_wrong] ^= 1;
    }
  }
  return {false, options.max_rounds, factorisations};
}

}  // namespace

void NormalLcpScratch::reserve(Eigen::Index points) {
  if (change.size() >= points) return;
  diagonal.resize(points);
  rhs.resize(points);
  change.resize(points);
  speed.resize(points);
  pushing.resize(static_cast<std::size_t>(points));
  wrong.resize(static_cast<std::size_t>(points));
  pushing_row.resize(static_cast<std::size_t>(points));
  pushing_rows.reserve(static_cast<std::size_t>(points));
}

void NormalLcpScratch::release() {
  NormalLcpScratch empty;
  empty.k_pushing_dense.swap(k_pushing_dense);
  *this = std::move(empty);
}

void NormalLcpScratch::reserve_dense(Eigen::Index points) {
  if (k_pushing_dense.rows() < points) k_pushing_dense.resize(points, points);
}

NormalLcpResult solve_normal_lcp(const Eigen::Ref<const Eigen::MatrixXd>& k,
                                 const Eigen::Ref<const Eigen::VectorXd>& w0,
                                 const Eigen::Ref<const Eigen::VectorXd>& start,
                                 NormalLcpScratch& scratch, Eigen::Ref<Eigen::VectorXd> impulse,
                                 const NormalLcpOptions& options) {
  return solve_lcp(k, w0, start, scratch, impulse, options);
}

NormalLcpResult solve_normal_lcp(const SparseK& k, const Eigen::Ref<const Eigen::VectorXd>& w0,
                                 const Eigen::Ref<const Eigen::VectorXd>& start,
                                 NormalLcpScratch& scratch, Eigen::Ref<Eigen::VectorXd> impulse,
                                 const NormalLcpOptions& options) {
  return solve_lcp(k, w0, start, scratch, impulse, options);
}

}  // namespace gp
