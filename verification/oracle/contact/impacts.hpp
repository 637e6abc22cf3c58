#pragma once
// Impacts at the contacts that touch at an event: Newton's law of restitution at each point and
// Coulomb's law on the impulses, found together as an LCP of the velocities after the impact
// (friction_lcp.hpp, the same planar-friction shape as the contact forces):
//   ġ⁺ᵢ + eᵢ ġ⁻ᵢ ≥ 0 ⊥ pᵢ ≥ 0,
//   ṡ⁺ᵢ + βᵢ ≥ 0 ⊥ p₊ᵢ ≥ 0,  −ṡ⁺ᵢ + βᵢ ≥ 0 ⊥ p₋ᵢ ≥ 0,  μᵢ pᵢ − p₊ᵢ − p₋ᵢ ≥ 0 ⊥ βᵢ ≥ 0,
// eᵢ = C_R for a contact arriving faster than the rest speed and 0 otherwise: each contact ends
// its impact without slip, or slipping with its tangential impulse at μ times its normal one.
// One frictionless contact alone is IM:col2D, the SRS's own model, and several frictionless
// contacts the same LCP without friction variables. An arrival slower than the rest speed ends
// without a bounce: that is what ends the Zeno sequence of an inelastic ball. With C_R = 0 the
// impact never gains energy; with C_R > 0 and friction Newton's law can (Kane and Levinson's
// example), which the caller checks.

#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/contact/contact_kinematics.hpp"
#include "verification/oracle/contact/friction_lcp.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

struct Impulse {
  double normal;   ///< p ≥ 0 [N·s] along the contact's normal, on the first body
  double tangent;  ///< p_t [N·s] along its tangent, on the first body
};

/// The impulses of the LCP of `rows` (each row's normal_rate: the gap's rate after the impulses
/// less the impulses' share, plus e ġ⁻; its slip_rate likewise), one per row, with `velocity`
/// [m/s] and `angular_velocity` [rad/s] of every body changed by them. Impacts and the
/// time-stepping reference (stepping/moreau_jean.hpp) pose their problems this way. Throws
/// std::runtime_error if Lemke's method fails, which the copositive-plus matrix rules out.
std::vector<Impulse> solve_impulses(const World& world, std::span<const FrictionRow> rows,
                                    std::span<Vec2> velocity, std::span<double> angular_velocity);

/// The impulses at `contacts` (kinematics `kinematics`, taken before the impact), one each, with
/// the velocities `velocity` [m/s] and `angular_velocity` [rad/s] of every body changed by them.
/// Contacts that do not approach faster than `rest_speed` [m/s] only keep the others from
/// pushing them into each other. Throws std::runtime_error if no impulses satisfy the laws
/// (Lemke's method failed), which the problem's copositive-plus matrix rules out.
std::vector<Impulse> resolve_impacts(const World& world, std::span<const ActiveContact> contacts,
                                     std::span<const ContactKinematics> kinematics,
                                     double rest_speed, std::span<Vec2> velocity,
                                     std::span<double> angular_velocity);

}  // namespace gp::oracle
