#pragma once
// Impacts at the contacts that touch at an event. One contact alone is IM:col2D with its C_R.
// Several at once (a box landing flat, a ball striking a resting stack) take Newton's law at each
// point, with the impulses found together as an LCP:
//   ġ⁺ᵢ + eᵢ ġ⁻ᵢ ≥ 0 ⊥ pᵢ ≥ 0,
// eᵢ = C_R for a contact arriving faster than the rest speed and 0 otherwise, which for one
// contact is exactly IM:col2D. An arrival slower than the rest speed ends without a bounce: that
// is what ends the Zeno sequence of an inelastic ball. Impacts are frictionless, as IM:col2D is.

#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/contact/contact_kinematics.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// The impulses p ≥ 0 [N·s] at `contacts` (kinematics `kinematics`, taken before the impact),
/// one each, with the velocities `velocity` [m/s] and `angular_velocity` [rad/s] of every body
/// changed by them. Contacts that do not approach faster than `rest_speed` [m/s] only keep the
/// others from pushing them into each other. Throws std::runtime_error if no impulses satisfy
/// the law (Lemke's method failed), which a positive semidefinite problem rules out.
std::vector<double> resolve_impacts(const World& world, std::span<const ActiveContact> contacts,
                                    std::span<const ContactKinematics> kinematics,
                                    double rest_speed, std::span<Vec2> velocity,
                                    std::span<double> angular_velocity);

}  // namespace gp::oracle
