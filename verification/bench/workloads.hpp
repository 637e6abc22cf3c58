#pragma once
// The benchmark workloads (NFR:Performance): whole runs of scenes that ours, Chipmunk2D and
// Box2D all step alike.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/space.hpp"
#include "scene/scene.hpp"

namespace gp::bench {

/// One benchmark: `steps` steps of scene.dt from the scene's start.
struct Workload {
  std::string name;
  Scene scene;
  int steps;
  /// The body whose displacement over the run is reported (the top box of a pyramid, which moves
  /// only if the stack is unstable); none for workloads where bodies are meant to move.
  std::optional<BodyId> watched;
};

/// `bodies` point masses of 1 kg without shapes on a square grid 1 m apart, each with its own
/// velocity, under g = 9.81 m/s²; dt = 1/60 s. No contacts: this measures the integrator and
/// the per-body cost of a step.
Scene free_fall(std::size_t bodies);

/// The rule of scenes/generate.py's rain1000, widened for `balls` a multiple of 25: balls
/// (r = 0.5 m, density 1 kg/m², friction 0.6) in 25 rows of balls / 25 columns 1.5 m apart,
/// alternate rows offset by half a pitch, the lowest at y = 5 m, falling under g = 9.81 m/s² into
/// an open box of three static segments, walls 60 m high and 2 m of floor per column (80 m for
/// rain1000); dt = 1/60 s, duration 8 s, output every 0.1 s. Widening rather than heaping higher
/// keeps each ball's fall, heap depth and contacts as in rain1000, so that the time per ball shows
/// how an engine scales with the number of bodies. rain(1000) is scenes/rain1000.json. Throws
/// std::invalid_argument when balls is not a positive multiple of 25.
Scene rain(std::size_t balls);

/// The workloads that the targets of NFR:Performance name: free10000 (600 steps), rain1000
/// (scenes/rain1000.json) and pyramid20 (scenes/pyramid20.json, its top box watched), the last two
/// 1000 steps each.
std::vector<Workload> headline_workloads(const std::filesystem::path& scenes_dir);

/// The highest body of `scene` (a pyramid's top box), whose displacement a workload reports.
BodyId highest_body(const Scene& scene);

/// Box2D 3's benchmark scenes, written by `scenes/generate.py --bench DIR`, with its step counts:
/// large_pyramid (500 steps) and many_pyramids (200), each with its highest box watched, and
/// tumbler (750); `quick` leaves out many_pyramids.
std::vector<Workload> box2d_workloads(const std::filesystem::path& bench_scenes_dir, bool quick);

/// `w` with sleeping on (Settings::sleep), named w.name + "_sleep".
Workload sleeping(Workload w);

/// The headline workloads, then rain4000 and rain16000 (rain(), 1000 steps each) for how the
/// engines scale, then box2d_workloads(), then pyramid20 and many_pyramids with sleeping on;
/// `quick` leaves out rain16000 and many_pyramids.
std::vector<Workload> workloads(const std::filesystem::path& scenes_dir,
                                const std::filesystem::path& bench_scenes_dir, bool quick);

}  // namespace gp::bench
