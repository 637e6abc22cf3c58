#pragma once
// The hard cases of other solvers (Box2D's robustness samples, the Solver2D study), each a scene
// with the metric that tells a stable solver from one that breaks on it.

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace gp::verification {

/// What a stability case is judged by: the smaller, the more stable.
enum class StabilityMetric {
  /// m: the largest distance of a body from where it was set, at the end (a resting structure
  /// should stay where it stands; sinking, sliding and collapse all show as drift).
  Drift,
  /// m: the largest penetration between two bodies over the run (a heavy body pushing through a
  /// light one, bodies packed tighter than they fit).
  Overlap,
  /// m/s: the largest speed reached over the run (overlapping bodies pushed apart: the faster,
  /// the more energy the solver injects to separate them).
  Speed,
};

struct StabilityCase {
  std::string name;
  Scene scene;
  StabilityMetric metric;
  std::string why;  ///< why this metric, in a line
};

/// Every case, 60 Hz, 10 s, friction 0.6 unless named: pyramids of base 10 capped by a box 100,
/// 200 and 300 times denser; a 20 m box on two small triangles; boxes created overlapping by half
/// their size; a card house; an arch of trapezoids; discs confined in a box, more than fit; the
/// rain of 1000 discs into a box (scenes/rain1000.json, gravity 9.81 m/s²); the pyramid of base
/// 10 at the origin and 10 km away.
std::vector<StabilityCase> stability_cases();

}  // namespace gp::verification
