#pragma once
#include <cstddef>
#include <span>

#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:momentOfInertia — moment of inertia of a set of particles about an axis normal to the plane.
///   I = Σ m_j d_j²,   d_j = ‖p_j − axis‖
/// With parts instead of particles, add each part's own moment about its centre: that is the
/// parallel-axis theorem, which the engine applies to shapes.
/// @param masses     m_j [kg]
/// @param positions  p_j [m]
/// @param axis       point where the rotation axis crosses the plane [m]
/// @return I [kg·m²]
inline double moment_of_inertia(std::span<const double> masses, std::span<const Vec2> positions,
                                const Vec2& axis) {
  double moment = 0.0;
  for (std::size_t j = 0; j < masses.size(); ++j) {
    moment += masses[j] * (positions[j] - axis).squaredNorm();
  }
  return moment;
}

GP_REGISTER_MODEL("DD:momentOfInertia", dd, moment_of_inertia);

}  // namespace gp::dd
