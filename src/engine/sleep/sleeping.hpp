#pragma once
// Islands at rest stop costing (Settings::sleep). A sleeping body counts as static for the step's
// stages: it is not dynamic, so the broadphase pairs it with no other sleeping or static body, and
// it has no inverse mass, so nothing it touches moves it. It keeps its place until something
// wakes its island.

#include <cstdint>
#include <vector>

#include "engine/step/step_context.hpp"

namespace gp {

/// Union-find scratch for fall_asleep, kept by the caller so that a step does not allocate.
struct SleepScratch {
  std::vector<BodyId> parent;
  std::vector<double> least_still;  ///< s, per island root
};

/// Whether `body` sleeps; never in a space without sleeping, which keeps no sleep state.
inline bool asleep(const StepContext& c, BodyId body) {
  return !c.sleep_island.empty() && c.sleep_island[body] != kAwake;
}

/// Whether `body` has slept since the shapes were last placed (world_start, end_bounds): they
/// are still where it sleeps, as a sleeping body keeps its place.
inline bool placed_asleep(const StepContext& c, BodyId body) {
  return !c.placed_asleep.empty() && c.placed_asleep[body] != 0;
}

/// Notes, once the shapes are placed, the bodies placed asleep.
void note_placed_asleep(StepContext& c);

/// Whether the space stands still: every dynamic body sleeps, no kinematic body moves, and no
/// contact or warm start is left. Every stage of a step would then leave the state as it is, and
/// the step only advances the clock.
bool stands_still(const StepContext& c);

/// Wakes every body of the island `body` sleeps in; nothing if it is awake.
void wake_island(StepContext& c, BodyId body);

/// Wakes the islands that a candidate pair of the broadphase joins to an awake dynamic body, or
/// that a moving kinematic body's swept box reaches. Returns whether any woke.
bool wake_touched(StepContext& c);

/// Holds the sleeping bodies where they fell asleep, after the integrator moved every body.
void hold_sleeping(StepContext& c);

/// Adds the sub-step to the still time of each awake dynamic body that feels gravity alone and
/// moves slower than the thresholds (else resets it), then puts to sleep every island of bodies
/// joined by contacts whose bodies have all been still for Settings::time_to_sleep.
void fall_asleep(StepContext& c, SleepScratch& scratch);

}  // namespace gp
