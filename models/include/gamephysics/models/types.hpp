#pragma once
// Vector types and the 2D products that stand in for the SRS's 3D operators (A:objectDimension).

#include <Eigen/Core>

namespace gp {

/// A 2D vector in SI units; what it measures is stated where it is used.
using Vec2 = Eigen::Vector2d;

/// z-component of the 3D cross product a × b of two in-plane vectors (the only one that is
/// non-zero). Units: product of the units of a and b.
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// In-plane vector (ω ẑ) × u for a rotation rate ω about the z-axis. Units: units of ω times u.
inline Vec2 cross(double omega, const Vec2& u) {
  return {-omega * u.y(), omega * u.x()};
}

}  // namespace gp
