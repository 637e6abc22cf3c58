#pragma once
// The contact forces between events, with every active contact's mode fixed: each touching
// contact keeps its gap's acceleration at zero (g̈ = 0), each sticking contact its slip's
// (ṡ = 0), and a sliding contact's friction is −μ f_n along its slip. That is a linear system
// in the force magnitudes; where the forces are not unique (a box resting on two points, whose
// tangential forces can be shared in any way), the least-norm forces are taken: the motion is the
// same for all of them.

#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/contact/contact_kinematics.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

struct ContactForce {
  double normal;   ///< f_n [N], ≥ 0 while the contact holds
  double tangent;  ///< f_t [N] along the contact's tangent, on the first body
  /// Whether these are the only forces that hold the modes (the system has full rank); else
  /// they are the least-norm share, and a negative f_n says nothing of a lift-off.
  bool unique;
};

/// The forces of `contacts` (kinematics `kinematics`, one each) and, added into `linear` and
/// `angular` (on entry the applied accelerations of every body, m/s² and rad/s²), the
/// accelerations they cause.
std::vector<ContactForce> solve_contact_forces(const World& world,
                                               std::span<const ActiveContact> contacts,
                                               std::span<const ContactKinematics> kinematics,
                                               std::span<Vec2> linear, std::span<double> angular);

}  // namespace gp::oracle
