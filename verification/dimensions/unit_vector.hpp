#pragma once
// A 2-vector whose components are Boost.Units quantities, with the free functions the model
// functions use on gp::Vec2 (gp/models/types.hpp), so that the dimensional audit instantiates the
// model functions themselves with units. Only vectors of one quantity add; products and quotients
// carry their units; assigning a vector to one of another dimension does not compile.

#include <boost/units/cmath.hpp>
#include <boost/units/quantity.hpp>
#include <cmath>
#include <type_traits>

namespace gp::verification {

template <class Q>
struct UnitVec2 {
  Q x{};
  Q y{};
};

template <class T>
constexpr bool is_unit_vector = false;
template <class Q>
constexpr bool is_unit_vector<UnitVec2<Q>> = true;

template <class Q>
UnitVec2<Q> operator+(const UnitVec2<Q>& a, const UnitVec2<Q>& b) {
  return {a.x + b.x, a.y + b.y};
}
template <class Q>
UnitVec2<Q> operator-(const UnitVec2<Q>& a, const UnitVec2<Q>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <class Q>
UnitVec2<Q> operator-(const UnitVec2<Q>& a) {
  return {-a.x, -a.y};
}
template <class Q>
UnitVec2<Q>& operator+=(UnitVec2<Q>& a, const UnitVec2<Q>& b) {
  return a = a + b;
}
template <class S, class Q>
requires(!is_unit_vector<S>) auto operator*(const S& s, const UnitVec2<Q>& v) {
  return UnitVec2<decltype(s * v.x)>{s * v.x, s * v.y};
}
template <class Q, class S>
requires(!is_unit_vector<S>) auto operator*(const UnitVec2<Q>& v, const S& s) {
  return UnitVec2<decltype(v.x * s)>{v.x * s, v.y * s};
}
template <class Q, class S>
requires(!is_unit_vector<S>) auto operator/(const UnitVec2<Q>& v, const S& s) {
  return UnitVec2<decltype(v.x / s)>{v.x / s, v.y / s};
}

template <class A, class B>
auto dot(const UnitVec2<A>& a, const UnitVec2<B>& b) {
  return a.x * b.x + a.y * b.y;
}
/// z-component of a × b.
template <class A, class B>
auto cross(const UnitVec2<A>& a, const UnitVec2<B>& b) {
  return a.x * b.y - a.y * b.x;
}
/// (ω ẑ) × u.
template <class S, class Q>
requires(!is_unit_vector<S>) auto cross(const S& omega, const UnitVec2<Q>& u) {
  return UnitVec2<decltype(omega * u.x)>{-omega * u.y, omega * u.x};
}
template <class Q>
auto squared_norm(const UnitVec2<Q>& a) {
  return dot(a, a);
}
template <class Q>
Q norm(const UnitVec2<Q>& a) {
  using boost::units::sqrt;
  using std::sqrt;
  return sqrt(squared_norm(a));
}

}  // namespace gp::verification
