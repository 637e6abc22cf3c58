#pragma once
// Generalized vectors on two bodies, and how a force along one moves the other: the dense
// algebra of the oracle's contact problems (Delassus operator J M⁻¹ Jᵀ), written on the bodies'
// inverse masses and moments with no matrix of the whole system.

#include <Eigen/Core>
#include <cstddef>
#include <span>

#include "verification/oracle/contact/contact_kinematics.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// A generalized vector with entries on two bodies only: (Fₓ, F_y, τ) or (aₓ, a_y, α) on each.
struct BodyPairVector {
  std::size_t first;
  std::size_t second;
  Eigen::Vector3d on_first;
  Eigen::Vector3d on_second;
};

/// The row of `contact` as a generalized vector (the direction its force acts in).
inline BodyPairVector along(const ActiveContact& contact, const ContactRow& row) {
  return {contact.first, contact.second, row.first, row.second};
}

/// What the normal force of `contact` pushes along: its normal row, carrying the friction
/// f_t = −μ f_n sign(s) of a sliding contact.
inline BodyPairVector normal_push(const ActiveContact& contact, const ContactKinematics& k) {
  BodyPairVector push = along(contact, k.normal_row);
  if (contact.mode == ContactMode::Sliding) {
    const double share = contact.friction * contact.slip_sign;
    push.on_first -= share * k.tangent_row.first;
    push.on_second -= share * k.tangent_row.second;
  }
  return push;
}

/// row · M⁻¹ column [1/kg]: the rate at which `row` changes per unit of force along `column`.
double coupling(const World& world, const BodyPairVector& row, const BodyPairVector& column);

/// row · a for accelerations (or velocities) `linear`, `angular` of every body.
double dot(const BodyPairVector& row, std::span<const Vec2> linear,
           std::span<const double> angular);

/// Adds M⁻¹ `direction` · `magnitude` to every body's `linear` and `angular` entries: the
/// acceleration of a force, or the velocity change of an impulse (DD:impulseV, DD:torque).
void add_response(const World& world, const BodyPairVector& direction, double magnitude,
                  std::span<Vec2> linear, std::span<double> angular);

}  // namespace gp::oracle
