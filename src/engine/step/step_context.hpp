#pragma once
// What the stages of a step share: the space's bodies, shapes and settings, the clock, the state
// being advanced and the contacts found on the way. Each stage takes this, plus what is its own
// (a mechanism's scratch); no stage keeps a reference to it between steps.

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/collision/shape_pair.hpp"
#include "engine/core.hpp"
#include "engine/dynamics/force_model.hpp"
#include "engine/dynamics/integrator.hpp"
#include "engine/geometry/world_bounds.hpp"
#include "engine/geometry/world_shapes.hpp"
#include "engine/impacts/impacts.hpp"
#include "engine/solver/contact_set.hpp"
#include "engine/solver/warm_start.hpp"
#include "scene/settings.hpp"

namespace gp {

/// The sleep_island of a body that is awake.
inline constexpr std::uint32_t kAwake = ~std::uint32_t{0};

struct StepContext {
  explicit StepContext(const Settings& s)
      : settings(s), forces(s), integrator(make_integrator(s.integrator)) {}

  // The space, changed only by adding, editing and removing bodies.
  Settings settings;
  BodyInertia inertia;
  std::vector<char> dynamic;  ///< per body
  std::vector<BodyId> kinematic;
  BodyShapes shapes;
  ForceModel forces;
  std::unique_ptr<Integrator> integrator;
  bool collides = false;  ///< two shapes of different bodies, one of them dynamic

  // The clock and the state.
  double time = 0.0;                   ///< s, at the start of the sub-step being run
  double h = 0.0;                      ///< s, the sub-step's length (an impact may shorten it)
  double previous_h = 0.0;             ///< s, the last sub-step's, for warm starting
  MotionState state;                   ///< advanced by the stages
  MotionState start;                   ///< at the start of the sub-step
  Accelerations varying_acceleration;  ///< at the start, when the forces are not constant
  std::optional<Ballistic> motion;     ///< the paths from `start` under its accelerations

  // Collisions.
  WorldShapes world_start;           ///< the shapes placed at the start of h
  WorldBounds end_bounds;            ///< boxes holding them at the end of h, along `motion`
  std::span<const ShapePair> pairs;  ///< the candidate pairs the contacts are found for (in a
                                     ///< sub-step, without its impact pairs)
  /// Per pair: 1 when its contact touches (touches(), within Settings::linear_slop), set with
  /// the contacts.
  std::vector<std::uint8_t> touching_pairs;
  std::vector<ShapePair> impact_pairs;  ///< resolved at the end of the sub-step, at its t_c
  ContactSet contacts;                  ///< resting and persistent, solved over the sub-step
  ContactSet speculative_contacts;      ///< impacts on resting bodies, this step only
  std::vector<WarmStart> warm_starts;   ///< the impulses of the last sub-step's contacts

  // Sleeping (Settings::sleep), per body; empty without it.
  std::vector<double> still_for;            ///< s moved slower than the sleep thresholds
  std::vector<std::uint32_t> sleep_island;  ///< kAwake, or the island the body sleeps in
  BodyInertia asleep_inertia;               ///< what a sleeping body wakes up with
  /// 1 for a body asleep when world_start and end_bounds last placed its shapes, and since.
  std::vector<char> placed_asleep;

  // What the step reports.
  std::vector<Impact> impacts;  ///< resolved at their time of impact during the step
  int impacts_this_step = 0;    ///< counted against Settings::max_impacts_per_step

  /// Whether impacts may still be resolved this step.
  bool impacts_allowed() const { return impacts_this_step < settings.max_impacts_per_step; }
  /// The factor the previous sub-step's impulses carry over with into this one.
  double warm_start_scale() const {
    // Resting impulses grow with the step, so they carry over scaled by h / h_prev; never scaled
    // up, because after a short sub-step (an impact) they hold what stopped the impact, which
    // does not grow with the step.
    return previous_h > 0.0 ? std::min(1.0, h / previous_h) : 0.0;
  }
};

}  // namespace gp
