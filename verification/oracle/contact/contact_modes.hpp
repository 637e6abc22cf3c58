#pragma once
// Which contacts hold and how, decided at an event from the complementarity problem of the
// contact forces at the acceleration level (Baraff 1994; in the plane the friction cone is two
// half-lines, so the problem is an LCP with no linearisation):
//   g̈ ≥ 0 ⊥ f_n ≥ 0                         every touching contact
//   ṡ + β ≥ 0 ⊥ f₊ ≥ 0,  −ṡ + β ≥ 0 ⊥ f₋ ≥ 0,
//   μ f_n − f₊ − f₋ ≥ 0 ⊥ β ≥ 0              every contact with friction and no slip
// with f_t = f₊ − f₋, and f_t = −μ f_n sign(s) for the contacts already sliding.

#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/contact/contact_kinematics.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// Sets the mode of each of `contacts` (kinematics `kinematics`, applied accelerations `linear`,
/// `angular` of every body) and removes those that let go (f_n = 0 with g̈ > 0). A contact
/// sliding with |s| above `slip_tolerance` [m/s] slides; one already Sliding with a slip_sign
/// (its friction just reached its bound) keeps sliding that way; any other sticks or starts to
/// slip as the problem says. Returns false when the LCP has no solution Lemke's method
/// reaches (frictional paradoxes of Painlevé's kind).
bool choose_contact_modes(const World& world, std::vector<ActiveContact>& contacts,
                          std::span<const ContactKinematics> kinematics,
                          std::span<const Vec2> linear, std::span<const double> angular,
                          double slip_tolerance);

}  // namespace gp::oracle
