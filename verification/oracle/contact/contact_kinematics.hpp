#pragma once
// The gap and slip of an active contact, their rates, and how their second derivatives depend on
// the two bodies' accelerations: g̈ = J_n·a + b_n and ṡ = J_t·a + b_t, with a = (aₓ, a_y, α) of
// each body. The rows J are also the directions in which the contact's normal and tangential
// forces act on the bodies (the principle of virtual work), so one computation serves the contact
// forces, the impulses and the projection onto the constraints.

#include <Eigen/Core>
#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// A row of a contact's Jacobian: rate change = first·a_first + second·a_second + bias.
struct ContactRow {
  Eigen::Vector3d first;   ///< per (aₓ [m/s²], a_y [m/s²], α [rad/s²]) of the first body
  Eigen::Vector3d second;  ///< the same for the second body
  double bias;             ///< the part that does not depend on the accelerations
};

struct ContactKinematics {
  double gap;             ///< g [m]: positive apart
  double gap_rate;        ///< ġ [m/s]: positive separating
  double slip;            ///< s [m/s]: the first's material point relative to the second's, along t
  Vec2 normal;            ///< n: unit, from the second body towards the first
  Vec2 tangent;           ///< t = n rotated by +90°
  Vec2 point;             ///< m: the contact point, on the first body's surface
  Vec2 first_arm;         ///< m: from the first body's centre of mass to the point
  Vec2 second_arm;        ///< m: from the second body's centre of mass to the point
  ContactRow normal_row;  ///< g̈
  ContactRow tangent_row;  ///< ṡ
  /// m: on an edge, how far along it the vertex projects (0 at its start) and its length.
  double along_edge;
  double edge_length;
};

/// The kinematics of `contact` with its bodies in motions `first` and `second`. Vertex–edge:
/// g = (P − Q)·N − r with P the vertex, Q the edge's start and N its normal, all turning with their
/// bodies; vertex–vertex: g = |P − Q| − r. Exact, not linearised: the second derivatives include
/// the centripetal and Coriolis terms of the turning bodies and of the normal.
ContactKinematics contact_kinematics(const ActiveContact& contact, const Motion& first,
                                     const Motion& second);

/// The kinematics of each of `contacts`, its bodies at `motions` (every body's).
std::vector<ContactKinematics> kinematics_of(std::span<const ActiveContact> contacts,
                                             std::span<const Motion> motions);

}  // namespace gp::oracle
