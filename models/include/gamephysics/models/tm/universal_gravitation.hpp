#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::tm {

/// TM:UniversalGravLaw — Newton's law of universal gravitation.
///   F_g = G m₁ m₂ / ‖d‖² · d̂,   d̂ = d / ‖d‖
/// Sign convention (see srs/errata.md, E-GRAVITY-SIGN): d points from body 1 to body 2, so the
/// result is the attractive force on body 1 towards body 2; d̂ is dimensionless.
/// @param G         gravitational constant [m³/(kg·s²)]
/// @param mass1     mass m₁ of the body the force acts on [kg]
/// @param mass2     mass m₂ of the attracting body [kg]
/// @param distance  d = p₂ − p₁, from body 1's centre of mass to body 2's [m], d ≠ 0
/// @return force on body 1 [N]
template <class Force = Vec2, class GravitationalConstant = double, class Mass = double,
          class Displacement = Vec2>
inline Force gravitational_force(models::In<GravitationalConstant> G, models::In<Mass> mass1,
                                 models::In<Mass> mass2, models::In<Displacement> distance) {
  const auto length = norm(distance);
  return G * mass1 * mass2 / (length * length) * (distance / length);
}

GP_REGISTER_MODEL("TM:UniversalGravLaw", tm, gravitational_force);

}  // namespace gp::tm
