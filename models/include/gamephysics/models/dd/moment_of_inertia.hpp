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
template <class Moment = double, class Mass = double, class Position = Vec2>
inline Moment moment_of_inertia(models::In<std::span<const Mass>> masses,
                                models::In<std::span<const Position>> positions,
                                models::In<Position> axis) {
  auto moment = models::zero<Moment>();
  for (std::size_t j = 0; j < masses.size(); ++j) {
    moment += masses[j] * squared_norm(positions[j] - axis);
  }
  return moment;
}

GP_REGISTER_MODEL("DD:momentOfInertia", dd, moment_of_inertia);

}  // namespace gp::dd
