#pragma once
// Two directions side by side, so that a model function of one direction gives its result for
// both in one evaluation on pairs of doubles: a point's normal and tangent effective masses then
// take one division instruction rather than two, with the same bits in each lane.

#include "gamephysics/models/types.hpp"

namespace gp {

/// Two doubles, a lane each: GCC's and Clang's vector type, whose +, −, × and ÷ act lane by lane
/// and round as on a double.
using DoublePair = double __attribute__((vector_size(16)));

/// Two 2D vectors: their x in one pair, their y in the other.
struct Vec2Pair {
  DoublePair x, y;
};

inline Vec2Pair operator-(const Vec2Pair& v) {
  return {-v.x, -v.y};
}

// The free functions of models/types.hpp lane by lane, each in the order of operations of the
// one for Vec2, so that lane k gives its bits for the vectors of lane k.

/// a × b for each vector b of the pair. Units: product of the units of a and b.
inline DoublePair cross(const Vec2& a, const Vec2Pair& b) {
  return a.x() * b.y - a.y() * b.x;
}

/// a · b lane by lane. Units: product of the units of a and b.
inline DoublePair dot(const Vec2Pair& a, const Vec2Pair& b) {
  return a.x * b.x + a.y * b.y;
}

/// ‖a‖² lane by lane. Units: square of the units of a.
inline DoublePair squared_norm(const Vec2Pair& a) {
  return a.x * a.x + a.y * a.y;
}

}  // namespace gp
