#pragma once
// The complementarity problem of Coulomb friction in the plane, posed on the contacts' rates:
// the gap's and the slip's accelerations for the contact forces (contact_modes.cpp), their
// velocities after the impulses of an impact (impacts.cpp). In the plane the friction cone is two
// half-lines, so the problem is an exact LCP:
//   w_n = G_n z + q_n ≥ 0 ⊥ f_n ≥ 0
//   ṡ + β ≥ 0 ⊥ f₊ ≥ 0,  −ṡ + β ≥ 0 ⊥ f₋ ≥ 0,  μ f_n − f₊ − f₋ ≥ 0 ⊥ β ≥ 0
// with ṡ = G_t z + q_t and f_t = f₊ − f₋ for every contact whose friction is undecided.

#include <Eigen/Core>
#include <span>
#include <vector>

#include "verification/oracle/contact/body_coupling.hpp"

namespace gp::oracle {

/// One contact's part of the problem.
struct FrictionRow {
  BodyPairVector normal;       ///< what w_n reads (the gap's row)
  BodyPairVector normal_push;  ///< what f_n pushes along (with a sliding contact's friction)
  BodyPairVector tangent;      ///< the slip's row, along which f₊ pushes
  double normal_rate;          ///< q_n: w_n with no force at any contact
  double slip_rate;            ///< q_t: ṡ with no force at any contact
  double friction;             ///< μ; the friction variables exist only with `undecided`
  bool undecided;              ///< f₊, f₋, β are unknowns of the problem
};

/// Where a contact's variables sit in z: its normal force, and f₊, f₋, β after `plus`.
struct FrictionSlots {
  Eigen::Index normal;
  Eigen::Index plus = -1;  ///< -1: no friction variables
};

struct FrictionLcp {
  Eigen::MatrixXd M;
  Eigen::VectorXd q;
  std::vector<FrictionSlots> slots;  ///< one per row
  std::vector<BodyPairVector> push;  ///< what each variable of z pushes along (β: nothing)
};

/// The LCP of `rows` on the bodies of `world` (their inverse masses and moments).
FrictionLcp friction_lcp(const World& world, std::span<const FrictionRow> rows);

}  // namespace gp::oracle
