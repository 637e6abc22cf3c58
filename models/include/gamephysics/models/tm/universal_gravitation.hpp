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
inline Vec2 gravitational_force(double G, double mass1, double mass2, const Vec2& distance) {
  const double norm = distance.norm();
  return G * mass1 * mass2 / (norm * norm) * (distance / norm);
}

GP_REGISTER_MODEL("TM:UniversalGravLaw", tm, gravitational_force);

}  // namespace gp::tm
