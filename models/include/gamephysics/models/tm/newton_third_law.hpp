#pragma once
#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::tm {

/// TM:NewtonThirdLawMot — Newton's third law of motion, F₁ = −F₂.
/// @param force  force F₁ that one body exerts on the other [N] (a force or, integrated over the
///               contact, an impulse [N·s]: the law holds for both)
/// @return the reaction F₂ = −F₁ that the other body exerts back [same units]
template <class Force = Vec2>
inline Force reaction_force(models::In<Force> force) {
  return -force;
}

GP_REGISTER_MODEL("TM:NewtonThirdLawMot", tm, reaction_force);

}  // namespace gp::tm
