#pragma once
// The stages of a step, defined once: the step runs this table, and `simulate --explain` prints
// it, so that the two cannot drift apart.
//
// A step runs in one of two passes. The local pass advances the whole step at once and resolves
// each impact at its time of impact for its own bodies (exact when every body follows a ballistic
// path: constant forces and an integrator exact along it). The sub-step pass ends a sub-step of
// the whole space at the first impact, and repeats until the step is done; it is the fallback
// when a local pass cannot finish (after each sub-step, the rest of the step is tried as a local
// pass again: StepRunner::step), and the only pass when local impacts are not exact.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "engine/collision/collision_detection.hpp"
#include "engine/impacts/impacts.hpp"
#include "engine/impacts/local_impacts.hpp"
#include "engine/sleep/sleeping.hpp"
#include "engine/solver/contact_solver.hpp"
#include "engine/step/step_context.hpp"

namespace gp {

/// The mechanisms a step's stages run, each owning its scratch.
struct StepMechanisms {
  explicit StepMechanisms(const Settings& s) : detection(s.contact_margin) {}

  CollisionDetection detection;
  ImpactSearch impact_search;
  LocalImpacts local_impacts;
  ContactSolver solver;
  ContactSet impact_contacts;  ///< scratch of the impacts resolved at the end of a sub-step
  SleepScratch sleep;
};

/// Which pass of a step runs a stage (bits).
enum Pass : std::uint8_t {
  kLocalPass = 1,
  kSubStepPass = 2,
};

struct Stage {
  std::string_view name;
  std::string_view srs_ids;
  std::uint8_t passes;  ///< Pass bits
  /// Whether a space needs the stage at all; the step skips it, and --explain does not list it,
  /// when not.
  bool (*needed)(const StepContext&);
  /// What the stage does for this space, for --explain.
  std::string (*describe)(const StepContext&);
  /// Runs the stage; false when a local pass cannot finish and the step must be sub-stepped.
  bool (*run)(StepContext&, StepMechanisms&);
};

/// The stages in the order a pass runs them.
std::span<const Stage> step_stages();

/// Whether a step of this space starts with the local pass.
bool runs_local_pass(const StepContext& c);

}  // namespace gp
