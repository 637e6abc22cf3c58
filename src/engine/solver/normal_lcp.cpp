#include "engine/solver/normal_lcp.hpp"

#include <algorithm>

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

// Point i's speed w_i = w₀_i + (K + compliance) Δλ after the impulse changes `change` [m/s]: the
// one problem, K with its compliance, that every round works on (on which Murty's rule cannot
// cycle).
double speed_after(const Eigen::Ref<const Eigen::MatrixXd>& k,
                   const Eigen::Ref<const Eigen::VectorXd>& w0,
                   const Eigen::Ref<const Eigen::VectorXd>& change, Eigen::Index i) {
  return w0(i) + k.row(i).dot(change) + kCompliance * k(i, i) * change(i);
}

// Each point's Δλ when the points marked in scratch.pushing push (w = 0) and the others let go
// (λ = 0), into scratch.change. Returns false if K restricted to the pushing points is not
// positive definite.
bool solve_pushing_set(const Eigen::Ref<const Eigen::MatrixXd>& k,
                       const Eigen::Ref<const Eigen::VectorXd>& w0,
                       const Eigen::Ref<const Eigen::VectorXd>& start, NormalLcpScratch& scratch) {
  const Eigen::Index n = k.rows();
  auto change = scratch.change.head(n);
  scratch.pushing_rows.clear();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (scratch.pushing[i]) scratch.pushing_rows.push_back(static_cast<int>(i));
    change(i) = scratch.pushing[i] ? 0.0 : -start(i);
  }
  const auto a = static_cast<Eigen::Index>(scratch.pushing_rows.size());
  if (a == 0) return true;
  auto k_pushing = scratch.k_pushing.topLeftCorner(a, a);
  auto rhs = scratch.rhs.head(a);
  for (Eigen::Index r = 0; r < a; ++r) {
    const int i = scratch.pushing_rows[r];
    // The speed the free points' letting go leaves; the pushing points' changes, still 0 in
    // `change`, are the unknowns.
    rhs(r) = -speed_after(k, w0, change, i);
    for (Eigen::Index q = 0; q < a; ++q) k_pushing(r, q) = k(i, scratch.pushing_rows[q]);
    // A heap is often statically indeterminate (a box across two others: more points than the
    // bodies' vertical and turning freedoms), which makes K singular.
    k_pushing(r, r) *= 1.0 + kCompliance;
  }
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> factor(k_pushing);
  if (factor.info() != Eigen::Success) return false;
  factor.solveInPlace(rhs);
  for (Eigen::Index r = 0; r < a; ++r) change(scratch.pushing_rows[r]) = rhs(r);
  return true;
}

}  // namespace

void NormalLcpScratch::reserve(Eigen::Index points) {
  if (k_pushing.rows() >= points) return;
  k_pushing.resize(points, points);
  rhs.resize(points);
  change.resize(points);
  pushing.resize(static_cast<std::size_t>(points));
  wrong.resize(static_cast<std::size_t>(points));
  pushing_rows.reserve(static_cast<std::size_t>(points));
}

NormalLcpResult solve_normal_lcp(const Eigen::Ref<const Eigen::MatrixXd>& k,
                                 const Eigen::Ref<const Eigen::VectorXd>& w0,
                                 const Eigen::Ref<const Eigen::VectorXd>& start,
                                 NormalLcpScratch& scratch, Eigen::Ref<Eigen::VectorXd> impulse,
                                 int max_rounds) {
  const Eigen::Index n = k.rows();
  scratch.reserve(n);
  const auto change = scratch.change.head(n);
  // One scale for the whole island: the largest impulse at stake (the largest so far, and the
  // largest that alone would stop a closing point) and the largest speed (w₀, and what the
  // compliance adds to it).
  double impulse_scale = kTiny;
  double speed_scale = kTiny;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(k(i, i) > 0.0)) return {false, 0};  // a point no body can move: no solution
    impulse_scale = std::max(impulse_scale, start(i) + std::max(-w0(i) / k(i, i), 0.0));
    speed_scale = std::max(speed_scale, std::abs(w0(i)) + kCompliance * k(i, i) * start(i));
  }
  const double impulse_tolerance = kRoundOff * impulse_scale;
  const double speed_tolerance = kRoundOff * speed_scale;
  // A stack starting at rest pushes at every level, not only where gravity has already made the
  // points close.
  for (Eigen::Index i = 0; i < n; ++i) {
    scratch.pushing[i] = start(i) > 0.0 || w0(i) <= speed_tolerance;
  }
  Eigen::Index fewest_wrong = n + 1;
  int block_rounds_left = 0;
  for (int round = 1; round <= max_rounds; ++round) {
    if (!solve_pushing_set(k, w0, start, scratch)) return {false, round};
    Eigen::Index wrong = 0;
    Eigen::Index last_wrong = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      scratch.wrong[i] = scratch.pushing[i] ? start(i) + change(i) < -impulse_tolerance
                                            : speed_after(k, w0, change, i) < -speed_tolerance;
      if (scratch.wrong[i]) {
        ++wrong;
        last_wrong = i;
      }
    }
    if (wrong == 0) {
      impulse = (start + change).cwiseMax(0.0);
      return {true, round};
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
  return {false, max_rounds};
}

}  // namespace gp
