#pragma once
// A run of a scene as the verification suite compares it: every body's state at common instants,
// the impacts, and what the run cost.

#include <functional>
#include <string>
#include <vector>

#include "engine/core.hpp"
#include "engine/impacts/impacts.hpp"
#include "scene/body.hpp"
#include "scene/scene.hpp"
#include "scene/settings.hpp"

namespace gp::verification {

struct Trajectory {
  std::vector<double> times;                   ///< s
  std::vector<std::vector<BodyState>> states;  ///< states[k][body] at times[k]
  std::vector<Impact> impacts;                 ///< collisions, in time order
  double cpu_seconds = 0.0;                    ///< CPU time of the run
};

/// The scene run by the game engine with `integrator` and step `dt` [s], its state recorded after
/// every step (output instants k·dt and the end).
Trajectory run_engine(const Scene& scene, IntegratorKind integrator, double dt);

/// CPU seconds the engine takes to run the scene with `integrator` and step `dt` [s], without
/// recording anything: the median of repeated runs, repeated for at least 0.1 s in all.
double time_engine(const Scene& scene, IntegratorKind integrator, double dt);

/// The first `n` output instants of `t` and the impacts up to the last of them.
Trajectory first_instants(const Trajectory& t, std::size_t n);

/// The output instants k·step up to `duration` and the end [s], as the engine records them.
std::vector<double> output_instants(double duration, double step);

/// CPU time of this process [s].
double cpu_now();

/// The median of the CPU seconds that repeated calls of `timed_run` return (each times what it
/// runs, leaving out its set-up), over at least 3 calls and 0.1 s in all.
double median_cpu_seconds(const std::function<double()>& timed_run);

/// The states of `run` at `instants` [s] (each a step end of the run, within 1e-9 s).
Trajectory sample_at(const Trajectory& run, const std::vector<double>& instants);

/// The largest |position| and |velocity| of a run: the scales that make its errors relative.
struct Scales {
  double position = 0.0;  ///< m
  double velocity = 0.0;  ///< m/s
};
Scales scales_of(const Trajectory& run);

/// The differences between a run and a reference at their common instants (the same times).
struct Differences {
  double position = 0.0;              ///< m, largest over bodies and instants
  double orientation = 0.0;           ///< rad, largest, the shorter way round
  double velocity = 0.0;              ///< m/s, largest
  double angular_velocity = 0.0;      ///< rad/s, largest
  double end_position = 0.0;          ///< m, largest at the last instant
  double end_velocity = 0.0;          ///< m/s, largest at the last instant
  double collision_time = 0.0;        ///< s, largest |t_c − t_c,ref| over matched impacts
  std::size_t unmatched_impacts = 0;  ///< impacts in one run with no counterpart in the other
};

/// Compares `run` with `reference` (the same instants and bodies; throws std::invalid_argument
/// otherwise). Impacts are matched in order per pair of bodies.
Differences compare(const Trajectory& run, const Trajectory& reference);

}  // namespace gp::verification
