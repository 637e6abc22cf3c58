#include "verification/oracle/contact/lemke.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace gp::oracle {

namespace {

// How the ratio test breaks ties: by the lowest basic variable (fast, and what every problem but
// the most degenerate needs), or lexicographically on [B⁻¹] / pivot, the rule that cannot cycle.
enum class Ties { LowestVariable, Lexicographic };

// The tableau [I  −M  −e | q] of Lemke's method: n rows, columns 0..n−1 for w, n..2n−1 for z,
// 2n for the artificial variable z₀ and 2n+1 for the right-hand side.
class Tableau {
 public:
  Tableau(const Eigen::MatrixXd& M, const Eigen::VectorXd& q)
      : n_(q.size()), t_(Eigen::MatrixXd::Zero(n_, 2 * n_ + 2)), basis_(n_) {
    t_.leftCols(n_).setIdentity();
    t_.middleCols(n_, n_) = -M;
    t_.col(2 * n_).setConstant(-1.0);
    t_.col(2 * n_ + 1) = q;
    for (Eigen::Index i = 0; i < n_; ++i) basis_[i] = i;
  }

  Eigen::Index artificial() const { return 2 * n_; }
  Eigen::Index complement(Eigen::Index v) const { return v < n_ ? v + n_ : v - n_; }
  double rhs(Eigen::Index row) const { return t_(row, 2 * n_ + 1); }

  /// Makes `column` basic in `row`; returns the variable that leaves the basis.
  Eigen::Index pivot(Eigen::Index row, Eigen::Index column) {
    t_.row(row) /= t_(row, column);
    for (Eigen::Index i = 0; i < n_; ++i) {
      if (i != row && t_(i, column) != 0.0) t_.row(i) -= t_(i, column) * t_.row(row);
    }
    const Eigen::Index leaving = basis_[row];
    basis_[row] = column;
    return leaving;
  }

  /// The row whose basic variable leaves when `column` enters (minimum ratio test), z₀ among
  /// ties so that the method ends as soon as it can, else by `ties`; -1 on a ray (no row limits
  /// the entering variable).
  Eigen::Index leaving_row(Eigen::Index column, double tolerance, Ties ties) const {
    double least = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < n_; ++i) {
      const double a = t_(i, column);
      if (a > tolerance) least = std::min(least, std::max(rhs(i), 0.0) / a);
    }
    if (!std::isfinite(least)) return -1;
    const double slack = 1e-12 * std::max(1.0, least);
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < n_; ++i) {
      const double a = t_(i, column);
      if (a <= tolerance || std::max(rhs(i), 0.0) / a > least + slack) continue;
      if (basis_[i] == artificial()) return i;
      if (best < 0 || (ties == Ties::Lexicographic ? lexicographically_less(i, best, column)
                                                   : basis_[i] < basis_[best])) {
        best = i;
      }
    }
    return best;
  }

  Eigen::VectorXd z() const {
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n_);
    for (Eigen::Index i = 0; i < n_; ++i) {
      if (basis_[i] >= n_ && basis_[i] < 2 * n_) z[basis_[i] - n_] = std::max(rhs(i), 0.0);
    }
    return z;
  }

 private:
  // Row i's [B⁻¹] / its pivot entry before row k's, entry by entry (B⁻¹ is the tableau's first n
  // columns, the identity of w at the start).
  bool lexicographically_less(Eigen::Index i, Eigen::Index k, Eigen::Index column) const {
    const double ai = t_(i, column);
    const double ak = t_(k, column);
    for (Eigen::Index j = 0; j < n_; ++j) {
      const double u = t_(i, j) / ai;
      const double v = t_(k, j) / ak;
      const double slack = 1e-12 * std::max({1.0, std::abs(u), std::abs(v)});
      if (u < v - slack) return true;
      if (u > v + slack) return false;
    }
    return basis_[i] < basis_[k];
  }

  Eigen::Index n_;
  Eigen::MatrixXd t_;
  std::vector<Eigen::Index> basis_;
};

}  // namespace

namespace {

std::optional<Eigen::VectorXd> lemke(const Eigen::MatrixXd& M, const Eigen::VectorXd& q,
                                     Ties ties) {
  const Eigen::Index n = q.size();
  Eigen::Index start = 0;
  if (n == 0 || q.minCoeff(&start) >= 0.0) return Eigen::VectorXd::Zero(n);
  // Entries of a pivot column this small against the problem's scale are round-off.
  const double tolerance = 1e-13 * std::max(1.0, M.cwiseAbs().maxCoeff());
  Tableau tableau(M, q);
  Eigen::Index entering = tableau.complement(tableau.pivot(start, tableau.artificial()));
  // Each pivot visits a distinct almost-complementary basis; far fewer than these are needed.
  const Eigen::Index limit = 50 * (n + 1);
  for (Eigen::Index step = 0; step < limit; ++step) {
    const Eigen::Index row = tableau.leaving_row(entering, tolerance, ties);
    if (row < 0) return std::nullopt;
    const Eigen::Index leaving = tableau.pivot(row, entering);
    if (leaving == tableau.artificial()) {
      Eigen::VectorXd z = tableau.z();
      const double scale = std::max(1.0, z.cwiseAbs().maxCoeff());
      for (double& v : z) {
        if (v < 1e-14 * scale) v = 0.0;
      }
      return z;
    }
    entering = tableau.complement(leaving);
  }
  return std::nullopt;
}

}  // namespace

std::optional<Eigen::VectorXd> solve_lcp(const Eigen::MatrixXd& M, const Eigen::VectorXd& q) {
  // Redundant contacts (a jammed lattice, a pile) give degenerate problems with many zero
  // right-hand sides, on which the first rule can cycle or end on a ray.
  if (auto z = lemke(M, q, Ties::LowestVariable)) return z;
  return lemke(M, q, Ties::Lexicographic);
}

}  // namespace gp::oracle
