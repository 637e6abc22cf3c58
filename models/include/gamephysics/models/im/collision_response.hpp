#pragma once
#include <algorithm>

#include "gamephysics/models/dd/chasles_theorem.hpp"
#include "gamephysics/models/dd/impulse.hpp"
#include "gamephysics/models/dd/relative_velocity.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/gd/collision_impulse.hpp"
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/tm/newton_third_law.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::im {

/// One of the two bodies of a collision, at the instant of contact t_c.
struct CollidingBody {
  double inverse_mass;      ///< 1/m [1/kg]; 0 for an immovable (static) body
  double inverse_moment;    ///< 1/I [1/(kg·m²)]; 0 for a body that cannot rotate
  Vec2 velocity;            ///< v of the centre of mass [m/s]
  double angular_velocity;  ///< ω [rad/s]
  Vec2 arm;                 ///< u_P, from the centre of mass to the contact point P [m]
};

/// Velocities of both bodies just after the collision, and the impulse magnitude.
struct CollisionResponse {
  Vec2 velocity_a;            ///< v_A(t_c⁺) [m/s]
  double angular_velocity_a;  ///< ω_A(t_c⁺) [rad/s]
  Vec2 velocity_b;            ///< v_B(t_c⁺) [m/s]
  double angular_velocity_b;  ///< ω_B(t_c⁺) [rad/s]
  double impulse;             ///< j ≥ 0 [N·s]
};

/// IM:col2D — collision response of two 2D rigid bodies at a vertex-to-edge contact.
///   v_A(t_c⁺) = v_A(t_c) + j n / m_A          ω_A(t_c⁺) = ω_A(t_c) + (u_AP × j n) / I_A
///   v_B(t_c⁺) = v_B(t_c) − j n / m_B          ω_B(t_c⁺) = ω_B(t_c) − (u_BP × j n) / I_B
/// with j from GD:impulse. The SRS states only the first equation (srs/errata.md E-IM-COL2D);
/// body B's impulse is the reaction −j n (TM:NewtonThirdLawMot). When the contact points are
/// already separating (v_i^AB · n ≥ 0) no impulse is applied: a contact can only push.
/// @param a            body A
/// @param b            body B
/// @param normal       unit collision normal n, pointing from B towards A [1]
/// @param restitution  C_R, 0 ≤ C_R ≤ 1 [1]
inline CollisionResponse collision_response(const CollidingBody& a, const CollidingBody& b,
                                            const Vec2& normal, double restitution) {
  const Vec2 velocity_ap = dd::point_velocity(a.velocity, a.angular_velocity, a.arm);
  const Vec2 velocity_bp = dd::point_velocity(b.velocity, b.angular_velocity, b.arm);
  const Vec2 relative = dd::relative_velocity(velocity_ap, velocity_bp);
  const double j = std::max(
      0.0, gd::collision_impulse(restitution, relative, normal, a.inverse_mass, b.inverse_mass,
                                 a.inverse_moment, b.inverse_moment, a.arm, b.arm));
  const Vec2 impulse_on_a = j * normal;
  const Vec2 impulse_on_b = tm::reaction_force(impulse_on_a);
  return {a.velocity + dd::velocity_change_from_impulse(impulse_on_a, a.inverse_mass),
          a.angular_velocity + dd::torque(a.arm, impulse_on_a) * a.inverse_moment,
          b.velocity + dd::velocity_change_from_impulse(impulse_on_b, b.inverse_mass),
          b.angular_velocity + dd::torque(b.arm, impulse_on_b) * b.inverse_moment, j};
}

GP_REGISTER_MODEL("IM:col2D", im, collision_response, "DD:chaslesThm", "DD:reVeInColl",
                  "GD:impulse", "TM:NewtonThirdLawMot", "DD:impulseV", "DD:torque");

}  // namespace gp::im
