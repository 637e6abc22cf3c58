#pragma once
// Doubles kept as floats where half the room is worth it, rounded outwards so that what a float
// bounds it still bounds. Internal to collision/.

#include <cmath>
#include <limits>

namespace gp {

/// The largest float not above `x`.
inline float float_below(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
}

/// The smallest float not below `x`.
inline float float_above(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace gp
