#pragma once
// A run of a scene: its space stepped from t = 0 to the end, stopping on every output instant.

#include <functional>

#include "engine/space.hpp"
#include "scene/scene.hpp"

namespace gp {

/// Steps `space`, built from `scene` and still at t = 0, to scene.duration with steps of
/// scene.dt, shortening the step that would cross an output instant (OutputTimes) so that it ends
/// on it; an interval within 10⁻⁶·dt of a whole number of steps takes that number of steps of
/// exactly dt, so that the steps, and the trajectory, do not depend on output_dt when it is a
/// multiple of dt. Calls at_output(t) at each instant, t = 0 first and t = scene.duration last,
/// with t exactly k·output_dt or the duration. Throws NumericalError when a state becomes
/// non-finite.
void run_scene(Space& space, const Scene& scene, const std::function<void(double t)>& at_output);

/// The same stepping for any engine (the peers): `step(dt)` advances it by dt [s].
void run_steps(const Scene& scene, const std::function<void(double dt)>& step,
               const std::function<void(double t)>& at_output);

}  // namespace gp
