#pragma once
// The V&V question of issue 19: is an integrator's numerical error below the spread of the
// outputs that the input uncertainty causes? Only then does comparing engines mean something.
// Both are measured on the final positions of the moving bodies.

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "verification/ensemble/sampler.hpp"
#include "verification/ensemble/uncertainty.hpp"

namespace gp::verification {

struct ErrorAgainstSpread {
  std::string integrator;
  double dt;               ///< s: the scene's step
  double numerical_error;  ///< m: RMS over moving bodies of |p − p_ref| at the end
  std::string reference;   ///< what p_ref is: the oracle, or a finer run where it cannot run
  double input_spread;     ///< m: RMS over moving bodies of the std of p at the end
  std::uint64_t samples;   ///< that ran (failed ones left out)
  std::uint64_t failed;
  bool below() const { return numerical_error < input_spread; }
};

/// For each game integrator: the nominal `scene`'s numerical error at its step against the oracle
/// (when `oracle_reference` and the oracle runs the scene) or else against RK4 at a sixteenth of
/// the step, and the input spread
/// over `samples` samples drawn with `spreads` (Sobol, `seed`), run in parallel (oneTBB).
std::vector<ErrorAgainstSpread> error_against_spread(const Scene& scene, const Spreads& spreads,
                                                     std::uint64_t samples, std::uint64_t seed,
                                                     bool oracle_reference);

}  // namespace gp::verification
