#include "verification/oracle/contact/lemke.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace gp::oracle {

namespace {

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

  /// The row whose basic variable leaves when `column` enters (minimum ratio test), preferring
  /// z₀ among ties so that the method ends as soon as it can, then the lowest basic variable;
  /// -1 on a ray (no row limits the entering variable).
  Eigen::Index leaving_row(Eigen::Index column, double tolerance) const {
    Eigen::Index best = -1;
    double best_ratio = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < n_; ++i) {
      const double a = t_(i, column);
      if (a <= tolerance) continue;
      const double ratio = std::max(rhs(i), 0.0) / a;
      if (best < 0) {
        best = i;
        best_ratio = ratio;
        continue;
      }
      const double slack = 1e-12 * std::max(1.0, best_ratio);
      const bool better = ratio < best_ratio - slack;
      const bool tie = !better && ratio <= best_ratio + slack;
      if (better || (tie && (basis_[i] == artificial() ||
                             (basis_[best] != artificial() && basis_[i] < basis_[best])))) {
        best = i;
        best_ratio = std::min(best_ratio, ratio);
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
  Eigen::Index n_;
  Eigen::MatrixXd t_;
  std::vector<Eigen::Index> basis_;
};

}  // namespace

std::optional<Eigen::VectorXd> solve_lcp(const Eigen::MatrixXd& M, const Eigen::VectorXd& q) {
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
    const Eigen::Index row = tableau.leaving_row(entering, tolerance);
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

}  // namespace gp::oracle
