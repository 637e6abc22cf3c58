#pragma once
// The oracle tests' comparison with a closed form, at the precision the oracle must achieve.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace gp::test {

/// What the oracle must achieve against a closed form [1].
inline constexpr double kOracleRelative = 1e-9;

/// |actual − expected| ≤ 1e-9 · max(|expected|, scale): relative, except for quantities that are
/// (near) zero, which are compared with the scale of the problem (in their units).
inline void check_near(double actual, double expected, double scale = 1.0) {
  INFO(std::setprecision(17) << "actual " << actual << ", expected " << expected);
  CHECK(std::abs(actual - expected) <= kOracleRelative * std::max(std::abs(expected), scale));
}

}  // namespace gp::test
