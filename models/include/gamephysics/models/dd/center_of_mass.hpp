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
template <class Position = Vec2, class Mass = double>
inline Position center_of_mass(models::In<std::span<const Mass>> masses,
                               models::In<std::span<const Position>> positions) {
  auto weighted = models::zero<models::Product<Mass, Position>>();
  auto total_mass = models::zero<Mass>();
  for (std::size_t j = 0; j < masses.size(); ++j) {
    weighted += masses[j] * positions[j];
    total_mass += masses[j];
  }
  return weighted / total_mass;
}

GP_REGISTER_MODEL("DD:ctrOfMass", dd, center_of_mass);

}  // namespace gp::dd
