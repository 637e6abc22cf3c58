#pragma once
// The non-contact accelerations of the oracle's bodies: uniform gravity, pairwise gravitation
// (TM:UniversalGravLaw through GD:accelGravity), constant forces and torques, and a force at a
// body-frame point (DD:torque), through IM:transMot and IM:rotMot.

#include <span>

#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// The applied accelerations of every body of `world` in the state `motion` (one per body, in
/// order): linear [m/s²] and angular [rad/s²], 0 for static and kinematic bodies and angular 0 for
/// a body that does not rotate. Pairwise gravitation acts between dynamic bodies only, as the
/// scene format states. The forces of a scene do not depend on time.
void applied_accelerations(const World& world, std::span<const Motion> motion,
                           std::span<Vec2> linear, std::span<double> angular);

}  // namespace gp::oracle
