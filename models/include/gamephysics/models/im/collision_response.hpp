#pragma once
#include <algorithm>
#include <utility>

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
template <class InverseMass = double, class InverseMoment = double, class Velocity = Vec2,
          class AngularVelocity = double, class Arm = Vec2>
struct BasicCollidingBody {
  using InverseMassType = InverseMass;
  using InverseMomentType = InverseMoment;
  using VelocityType = Velocity;
  using AngularVelocityType = AngularVelocity;
  using ArmType = Arm;
  InverseMass inverse_mass;          ///< 1/m [1/kg]; 0 for an immovable (static) body
  InverseMoment inverse_moment;      ///< 1/I [1/(kg·m²)]; 0 for a body that cannot rotate
  Velocity velocity;                 ///< v of the centre of mass [m/s]
  AngularVelocity angular_velocity;  ///< ω [rad/s]
  Arm arm;                           ///< u_P, from the centre of mass to the contact point P [m]
};
using CollidingBody = BasicCollidingBody<>;

/// Velocities of both bodies just after the collision, and the impulse magnitude.
template <class Velocity = Vec2, class AngularVelocity = double, class Impulse = double>
struct BasicCollisionResponse {
  Velocity velocity_a;                 ///< v_A(t_c⁺) [m/s]
  AngularVelocity angular_velocity_a;  ///< ω_A(t_c⁺) [rad/s]
  Velocity velocity_b;                 ///< v_B(t_c⁺) [m/s]
  AngularVelocity angular_velocity_b;  ///< ω_B(t_c⁺) [rad/s]
  Impulse impulse;                     ///< j ≥ 0 [N·s]
};
using CollisionResponse = BasicCollisionResponse<>;

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
template <class Impulse = double, class Body = CollidingBody, class Normal = Vec2,
          class Restitution = double>
inline BasicCollisionResponse<typename Body::VelocityType, typename Body::AngularVelocityType,
                              Impulse>
collision_response(models::In<Body> a, models::In<Body> b, models::In<Normal> normal,
                   models::In<Restitution> restitution) {
  using Velocity = typename Body::VelocityType;
  using AngularVelocity = typename Body::AngularVelocityType;
  using Arm = typename Body::ArmType;
  using ImpulseVector = models::Product<Impulse, Normal>;
  using AngularImpulse = decltype(cross(std::declval<Arm>(), std::declval<ImpulseVector>()));
  const Velocity velocity_ap =
      dd::point_velocity<Velocity, AngularVelocity, Arm>(a.velocity, a.angular_velocity, a.arm);
  const Velocity velocity_bp =
      dd::point_velocity<Velocity, AngularVelocity, Arm>(b.velocity, b.angular_velocity, b.arm);
  const Velocity relative = dd::relative_velocity<Velocity>(velocity_ap, velocity_bp);
  const Impulse j = std::max(
      models::zero<Impulse>(),
      gd::collision_impulse<Impulse, Restitution, Velocity, Normal, typename Body::InverseMassType,
                            typename Body::InverseMomentType, Arm>(
          restitution, relative, normal, a.inverse_mass, b.inverse_mass, a.inverse_moment,
          b.inverse_moment, a.arm, b.arm));
  const ImpulseVector impulse_on_a = j * normal;
  const ImpulseVector impulse_on_b = tm::reaction_force<ImpulseVector>(impulse_on_a);
  const auto velocity_change = [](const ImpulseVector& impulse, const auto& inverse_mass) {
    return dd::velocity_change_from_impulse<Velocity, ImpulseVector,
                                            typename Body::InverseMassType>(impulse, inverse_mass);
  };
  const auto angular_impulse = [](const Arm& arm, const ImpulseVector& impulse) {
    return dd::torque<AngularImpulse, Arm, ImpulseVector>(arm, impulse);
  };
  return {a.velocity + velocity_change(impulse_on_a, a.inverse_mass),
          a.angular_velocity + angular_impulse(a.arm, impulse_on_a) * a.inverse_moment,
          b.velocity + velocity_change(impulse_on_b, b.inverse_mass),
          b.angular_velocity + angular_impulse(b.arm, impulse_on_b) * b.inverse_moment, j};
}

GP_REGISTER_MODEL("IM:col2D", im, collision_response, "DD:chaslesThm", "DD:reVeInColl",
                  "GD:impulse", "TM:NewtonThirdLawMot", "DD:impulseV", "DD:torque");

}  // namespace gp::im
