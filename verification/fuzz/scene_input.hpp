#pragma once
// One input of the scene-file fuzzer: bytes that must end in a loaded scene, an InputError or a
// NumericalError, never in a crash, a hang or another exception (FR:Verify-Physical_Constraints).
// The fuzzer (fuzz_scene.cpp) and the ctest that replays its corpus and its crash inputs
// (tests/fuzz/) both go through run_scene_input, so a crash found by one is replayed by the other.

#include <cstddef>
#include <string>

namespace gp::fuzz {

/// How an input ended.
enum class SceneInputOutcome {
  kRan,             ///< a valid scene, run for the bounded time
  kInputError,      ///< the loader or build_space rejected it
  kNumericalError,  ///< valid, but its run produced a non-finite state
};

/// Bounds on the run of a valid scene, so that a valid but costly scene cannot hang the fuzzer.
/// The fuzz target is a Debug build with sanitizers, some 30 times slower than Release, and
/// libFuzzer calls an input that takes over 5 s a hang. A step's cost grows with the pairs of
/// overlapping shapes (all of them when the shapes are piled on one spot) times the solver's
/// passes: the bounds keep the costliest such input under 2 s (1.8 s measured; README).
struct SceneInputLimits {
  std::size_t max_bodies = 32;  ///< larger scenes are loaded and built, not run
  std::size_t max_shapes = 32;  ///< over all bodies, likewise
  double max_steps = 120;       ///< time steps of the run at most
  double max_outputs = 100;     ///< output instants (CSV rows per body) at most
  int max_passes = 20;          ///< velocity and position passes a step at most, each
  int max_direct_points = 64;   ///< points of an island solved directly at most
};

/// Parses `text` as a scene file, checking every value as given, and builds its space; within
/// `limits`, with its solver settings cut to the limits, and then runs it from t = 0 for at most
/// limits.max_steps steps of its dt, writing the trajectory CSV to memory.
/// Returns how it ended; any exception other than InputError and NumericalError propagates.
SceneInputOutcome run_scene_input(const std::string& text, const SceneInputLimits& limits = {});

/// "ran", "input_error", "numerical_error": the prefix of the corpus files that expect it.
std::string outcome_name(SceneInputOutcome outcome);

}  // namespace gp::fuzz
