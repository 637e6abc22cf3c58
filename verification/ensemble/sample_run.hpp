#pragma once
// One sample of an ensemble: a perturbed scene run by the engine (and by the oracle when asked),
// reduced to what the ensemble's tables keep. A run that fails is recorded, not thrown.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scene/body_state.hpp"
#include "scene/scene.hpp"

namespace gp::verification {

/// Impacts whose times a sample keeps (the first ones, in time order).
inline constexpr std::size_t kRecordedImpacts = 3;

/// The oracle's verdict on a sample: its largest distance from the engine's run.
struct OracleComparison {
  std::string status;           ///< "ok", or why the oracle could not run the sample
  double position_error = 0.0;  ///< m: largest |p_engine − p_oracle| over bodies and instants
  double velocity_error = 0.0;  ///< m/s: the same for the velocities
};

struct SampleOutputs {
  std::vector<BodyState> final_states;  ///< every body at the end, in file order
  std::size_t impact_count = 0;
  std::vector<double> impact_times;  ///< s: the first kRecordedImpacts, or fewer
  std::vector<double> energy;        ///< J: total energy (invariants) at each output instant
  std::optional<OracleComparison> oracle;
  std::string error;  ///< empty, or why the run failed (e.g. NumericalError)
};

/// Runs `scene` in the engine from t = 0 to its duration, stopping on its output instants; with
/// `with_oracle`, also in the oracle (reference_options) and compares the two at every instant.
SampleOutputs run_sample(const Scene& scene, bool with_oracle);

}  // namespace gp::verification
