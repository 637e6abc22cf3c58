#pragma once
// Turning a body-frame vector into world axes: the one trigonometric step between a body's
// orientation and where its shapes, arms and normals point.

#include <cmath>

#include "gamephysics/models/types.hpp"

namespace gp::oracle {

/// `v` turned counter-clockwise by `angle` [rad] (units of v).
inline Vec2 rotated(const Vec2& v, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace gp::oracle
