#pragma once
// What is well posed about a chaotic pile (which body ends where depends on round-off): its
// mechanical energy over time, the time it takes to settle, and the settled heap's profile, the
// bodies' heights sorted. Both the engine's runs and the oracle's time-stepping reference are
// measured this way, and so is the reference's own error (its runs at h and h/2).

#include <vector>

#include "verification/suite/trajectory.hpp"

namespace gp::verification {

struct PileMeasures {
  std::vector<double> energy;  ///< J at each instant: Σ ½ m v² + ½ I ω² − m g·p (DD:kEnergy)
  double settle_time = 0.0;    ///< s: from when the kinetic energy stays below kSettledShare
                               ///< of the pile's drop (the run's end if it never does)
  std::vector<double> profile;  ///< m: the dynamic bodies' heights at the end, sorted
  double drop = 0.0;            ///< J: what the pile could lose falling to its lowest body's height
};

/// The kinetic energy below which a pile is settled, as a share of its drop [1]: 1e-3, a disc of
/// settle50 sliding at about 1 m/s.
inline constexpr double kSettledShare = 1e-3;

/// The measures of `run` (a run of `scene`, at least one instant); masses and moments from the
/// engine's set-up of `scene`, the same for every run measured.
PileMeasures measure_pile(const Scene& scene, const Trajectory& run);

/// How far apart two runs' measures are: the largest |ΔE(t)| and the settled heap's |ΔE| at the
/// end (its mean height), as shares of the drop [1], the difference of their settle times [s]
/// and the largest difference of their profiles [m].
struct PileDifferences {
  double energy = 0.0;
  double settled_energy = 0.0;
  double settle_time = 0.0;
  double profile = 0.0;
};
PileDifferences pile_differences(const PileMeasures& a, const PileMeasures& reference);

}  // namespace gp::verification
