#pragma once
// The oracle's own solver of linear complementarity problems: find z with
//   w = M z + q,  w ≥ 0,  z ≥ 0,  wᵀ z = 0,
// by Lemke's complementary pivoting. The oracle poses its contact problems this way (the contact
// forces at the acceleration level, the impulses of simultaneous impacts); it shares nothing with
// the engine's solvers (src/engine/contacts), so that a fault of either shows as a disagreement.

#include <Eigen/Core>
#include <optional>

namespace gp::oracle {

/// z solving the LCP (M square, q of its size), or nothing when Lemke's method ends on a ray (no
/// solution it can reach: a Painlevé-like contact problem) or exceeds its pivot limit. M need not
/// be symmetric; Lemke's method solves every LCP whose M is copositive-plus (positive
/// semidefinite M, and the 2D frictional contact problems built in contact_modes.cpp) that has a
/// solution. Entries of z within round-off of zero are zero.
std::optional<Eigen::VectorXd> solve_lcp(const Eigen::MatrixXd& M, const Eigen::VectorXd& q);

}  // namespace gp::oracle
