#pragma once
// Vector types and the 2D products that stand in for the SRS's 3D operators (A:objectDimension).
// The model functions are templates on their quantity types and use only the free functions
// below, so that the engine instantiates them with double and Vec2, and the dimensional audit
// (verification/dimensions/) with Boost.Units quantities and a unit-carrying 2-vector.

#include <Eigen/Core>
#include <type_traits>
#include <utility>

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

/// a · b. Units: product of the units of a and b.
inline double dot(const Vec2& a, const Vec2& b) {
  return a.dot(b);
}

/// ‖a‖². Units: square of the units of a.
inline double squared_norm(const Vec2& a) {
  return a.squaredNorm();
}

/// ‖a‖. Units: units of a.
inline double norm(const Vec2& a) {
  return a.norm();
}

namespace models {

// The model functions' parameters: a parameter of type `In<T>` does not take part in template
// argument deduction, so a call without template arguments uses the defaults (double, Vec2) and
// converts its arguments exactly as a function taking double and Vec2 would.
template <class T>
using In = const std::type_identity_t<T>&;

// Eigen's sums and products are expression templates; Plain names the value they evaluate to.
template <class T>
struct Plain {
  using type = T;
};
template <class T>
requires requires {
  typename T::PlainObject;
}
struct Plain<T> {
  using type = typename T::PlainObject;
};

/// Type of a * b, evaluated.
template <class A, class B>
using Product = typename Plain<decltype(std::declval<A>() * std::declval<B>())>::type;

/// The zero of a quantity or vector type.
template <class T>
T zero() {
  if constexpr (requires { T::Zero(); }) {
    return T::Zero();
  } else {
    return T{};
  }
}

/// One SI unit of a quantity type: 1.0 for double, 1 kg for a mass quantity.
template <class T>
T one() {
  if constexpr (std::is_arithmetic_v<T>) {
    return T(1);
  } else {
    return T::from_value(1.0);
  }
}

}  // namespace models
}  // namespace gp
