#pragma once
// Runs a step as the table of stages says (stages.hpp), and describes it from the same table.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/pipeline.hpp"
#include "engine/step/stages.hpp"
#include "engine/step/step_context.hpp"

namespace gp {

class StepRunner {
 public:
  explicit StepRunner(const Settings& settings);

  /// Advances `c` by dt [s]: the local pass when the space allows it, else (or when it cannot
  /// finish) sub-steps, each ending at an impact or at the end of the step.
  void step(StepContext& c, double dt);

  /// The stages of the table, each marked needed or not by this space, with what it does here.
  std::vector<PipelineStage> pipeline(const StepContext& c) const;

  /// How many times each stage of step_stages() ran, and how many passes of each kind ran.
  std::span<const std::uint64_t> stage_runs() const { return stage_runs_; }
  /// Whether the steps from now on time each stage (off by default: two clock reads a stage);
  /// pipeline() gives each stage's time.
  void time_stages(bool on) { timing_ = on; }
  std::uint64_t local_passes() const { return local_passes_; }
  std::uint64_t sub_steps() const { return sub_steps_; }
  /// Steps the space stood still through (stands_still), which ran no stage.
  std::uint64_t still_steps() const { return still_steps_; }

 private:
  /// Runs the stages of `pass` over a sub-step of h [s] from the current state; the time it
  /// advanced [s], or 0 when a local pass cannot finish (having changed no state).
  double run_pass(StepContext& c, Pass pass, double h);
  /// What every pass over h [s] does before its stages, and after them.
  static void begin_pass(StepContext& c, double h);
  static void end_pass(StepContext& c);
  /// Frees the room a space standing still does not use: its contacts', warm starts', candidate
  /// pairs' and manifolds'. A step that moves again finds them as a first step does.
  void release_room(StepContext& c);

  StepMechanisms mechanisms_;
  std::vector<std::uint64_t> stage_runs_;
  std::vector<double> stage_seconds_;
  bool timing_ = false;
  std::uint64_t local_passes_ = 0;
  std::uint64_t sub_steps_ = 0;
  std::uint64_t still_steps_ = 0;
  bool standing_still_ = false;  // at the last step
};

}  // namespace gp
