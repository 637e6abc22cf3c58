#pragma once
// Long runs of a scene (1e6 steps in `gamephysics longrun` and `gamephysics verify --long`):
// every state stays finite, no body leaves the box the scene starts in, and the resident memory
// does not grow once the run has settled (NFR:Correctness, FR:Calculate-Translation-Over-Time,
// FR:Determine-Collision-Response-Over-Time).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "verification/suite/check.hpp"

namespace gp::verification {

/// An axis-aligned box [m].
struct Box {
  Vec2 lower;
  Vec2 upper;
  bool contains(const Vec2& point) const;
};

/// The box no body of `scene` should leave: around the static bodies' shapes and every body's
/// starting position, `margin` [m] wider on each side. Nothing in a closed scene without energy
/// sources can carry a body beyond its walls or above the height it falls from.
Box starting_box(const Scene& scene, double margin);

/// The resident memory of this process [MiB] (/proc/self/statm).
double resident_mib();

struct MemorySample {
  long step;       ///< steps done when sampled
  double rss_mib;  ///< resident memory [MiB]
};

struct LongRunResult {
  long steps_done = 0;
  double wall_seconds = 0.0;
  std::string non_finite;  ///< the NumericalError's message; empty when every state was finite
  double max_abs_coordinate = 0;     ///< m: largest |x| or |y| of a dynamic body's centre of mass
  std::string first_outside;         ///< "body 'b' at step k": the first to leave the box, or empty
  std::vector<MemorySample> memory;  ///< at the start and at `samples` evenly spaced steps

  /// MiB: resident memory at the end less at the first sample after the start (the first tenth
  /// of the run lets the contact caches reach their working size).
  double memory_growth_mib() const;
};

/// m: how far outside its starting box a body may go (a resting body's contact slop is far less).
inline constexpr double kBoxMargin = 1.0;
/// Memory samples of a long run.
inline constexpr int kMemorySamples = 20;

/// MiB the resident memory may grow past the first tenth of a long run. A leak of one contact
/// record (~100 bytes) a step would add ~95 MiB over 1e6 steps; this allows for the allocator
/// keeping freed pages, not for a leak.
inline constexpr double kMaxMemoryGrowthMib = 2.0;

/// Called with each memory sample as it is taken, e.g. to show the progress of an hour-long run.
using LongRunProgress = std::function<void(const MemorySample&)>;

/// Builds the scene's space and steps it `steps` times by scene.dt (the scene's duration is not
/// used), checking every body against `box` after each step and sampling memory `samples` times.
/// Stops early at a non-finite state.
LongRunResult long_run(const Scene& scene, long steps, int samples, const Box& box,
                       const LongRunProgress& progress = {});

/// The report rows of a run labelled `label`: finite states, the box, memory (checked) and the
/// wall time (reported).
std::vector<Check> long_run_rows(const std::string& label, const LongRunResult& result);

/// `scene` with only its first `count` bodies (a smaller rain of the same file).
Scene first_bodies(Scene scene, std::size_t count);

}  // namespace gp::verification
