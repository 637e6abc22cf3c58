#pragma once
#include <cstddef>
#include <span>

#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:ctrOfMass — centre of mass of a set of particles (or of parts, each at its own centre).
///   p_CM = Σ m_j p_j / m_T,   m_T = Σ m_j
/// @param masses     m_j [kg], each > 0
/// @param positions  p_j [m], as many as masses
/// @return p_CM [m]
inline Vec2 center_of_mass(std::span<const double> masses, std::span<const Vec2> positions) {
  Vec2 weighted = Vec2::Zero();
  double total_mass = 0.0;
  for (std::size_t j = 0; j < masses.size(); ++j) {
    weighted += masses[j] * positions[j];
    total_mass += masses[j];
  }
  return weighted / total_mass;
}

GP_REGISTER_MODEL("DD:ctrOfMass", dd, center_of_mass);

}  // namespace gp::dd
