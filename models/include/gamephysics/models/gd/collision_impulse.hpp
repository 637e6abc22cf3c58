#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::gd {

/// GD:impulse — magnitude of the impulse that resolves a collision between rigid bodies A and B.
///   j = −(1 + C_R) v_i^AB · n / [ (1/m_A + 1/m_B) ‖n‖² + (u_AP × n)² / I_A + (u_BP × n)² / I_B ]
/// The SRS's ‖u_AP * n‖² is the square of the 2D cross product u_AP × n (srs/errata.md). Inverse
/// masses and moments are taken so that an immovable body (m, I → ∞) is exactly 0.
/// @param restitution        coefficient of restitution C_R, 0 ≤ C_R ≤ 1 [1]
/// @param relative_velocity  v_i^AB = v^AP − v^BP before the collision (DD:reVeInColl) [m/s]
/// @param normal             collision normal n, unit length, pointing from B towards A [1]
/// @param inverse_mass_a     1/m_A [1/kg]; 0 for an immovable body
/// @param inverse_mass_b     1/m_B [1/kg]
/// @param inverse_moment_a   1/I_A [1/(kg·m²)]
/// @param inverse_moment_b   1/I_B [1/(kg·m²)]
/// @param arm_a              u_AP, from A's centre of mass to the contact point P [m]
/// @param arm_b              u_BP, from B's centre of mass to the contact point P [m]
/// @return impulse magnitude j [N·s]; positive when the bodies approach (v_i^AB · n < 0)
template <class Impulse = double, class Restitution = double, class Velocity = Vec2,
          class Normal = Vec2, class InverseMass = double, class InverseMoment = double,
          class Arm = Vec2>
inline Impulse collision_impulse(models::In<Restitution> restitution,
                                 models::In<Velocity> relative_velocity, models::In<Normal> normal,
                                 models::In<InverseMass> inverse_mass_a,
                                 models::In<InverseMass> inverse_mass_b,
                                 models::In<InverseMoment> inverse_moment_a,
                                 models::In<InverseMoment> inverse_moment_b, models::In<Arm> arm_a,
                                 models::In<Arm> arm_b) {
  const auto arm_a_cross_n = cross(arm_a, normal);
  const auto arm_b_cross_n = cross(arm_b, normal);
  const auto effective_inverse_mass = (inverse_mass_a + inverse_mass_b) * squared_norm(normal) +
                                      arm_a_cross_n * arm_a_cross_n * inverse_moment_a +
                                      arm_b_cross_n * arm_b_cross_n * inverse_moment_b;
  return -(1.0 + restitution) * dot(relative_velocity, normal) / effective_inverse_mass;
}

GP_REGISTER_MODEL("GD:impulse", gd, collision_impulse);

}  // namespace gp::gd
