#include "engine/step/step_runner.hpp"

#include <chrono>
#include <string>

namespace gp {

StepRunner::StepRunner(const Settings& settings)
    : mechanisms_(settings),
      stage_runs_(step_stages().size(), 0),
      stage_seconds_(step_stages().size(), 0.0) {}

void StepRunner::step(StepContext& c, double dt) {
  c.impacts.clear();
  c.impacts_this_step = 0;
  // Settled piles asleep cost nothing: the step would leave them as they are, and they hold no
  // room for the contacts they no longer have.
  if (stands_still(c)) {
    if (!standing_still_) release_room(c);
    standing_still_ = true;
    ++still_steps_;
    begin_pass(c, dt);
    end_pass(c);
    return;
  }
  standing_still_ = false;
  if (runs_local_pass(c) && run_pass(c, kLocalPass, dt) > 0.0) return;
  c.impacts.clear();
  c.impacts_this_step = 0;
  // Each sub-step ends at an impact or at the end of the step; impacts are bounded per step.
  // After each, while impacts are still allowed, the rest of the step is tried as one local pass
  // again rather than a sub-step per impact (each costs a whole step): the impact that stopped
  // the last try may be behind. A failed try leaves the state as it was, and its impacts are not
  // kept. Past the limit, only sub-steps resolve what the step's end finds (impacts_allowed).
  for (double remaining = dt; remaining > 0.0;) {
    remaining -= run_pass(c, kSubStepPass, remaining);
    if (remaining <= 0.0 || !runs_local_pass(c) || !c.impacts_allowed()) continue;
    const std::size_t logged = c.impacts.size();
    const int counted = c.impacts_this_step;
    if (run_pass(c, kLocalPass, remaining) > 0.0) return;
    c.impacts.resize(logged);
    c.impacts_this_step = counted;
  }
}

double StepRunner::run_pass(StepContext& c, Pass pass, double h) {
  ++(pass == kLocalPass ? local_passes_ : sub_steps_);
  begin_pass(c, h);
  const std::span<const Stage> stages = step_stages();
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const Stage& stage = stages[i];
    if (!(stage.passes & pass) || !stage.needed(c)) continue;
    ++stage_runs_[i];
    const auto start =
        timing_ ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
    const bool finished = stage.run(c, mechanisms_);
    if (timing_) {
      stage_seconds_[i] +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    if (!finished) return 0.0;
  }
  end_pass(c);
  return c.h;
}

void StepRunner::begin_pass(StepContext& c, double h) {
  c.h = h;
  c.start = c.state;
  c.impact_pairs.clear();
  // A local pass that could not finish may have handed impacts over as speculative contacts:
  // they were made for its own step, and their pairs' impacts are the sub-steps' to find now.
  c.speculative_contacts.clear();
}

void StepRunner::release_room(StepContext& c) {
  c.contacts.release();
  c.speculative_contacts.release();
  c.warm_starts = std::vector<WarmStart>();
  c.touching_pairs = std::vector<std::uint8_t>();
  c.pairs = {};
  mechanisms_.detection.release();
}

void StepRunner::end_pass(StepContext& c) {
  c.time += c.h;
  c.previous_h = c.h;
}

std::vector<PipelineStage> StepRunner::pipeline(const StepContext& c) const {
  const bool local = runs_local_pass(c);
  std::vector<PipelineStage> out;
  const std::span<const Stage> stages = step_stages();
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const Stage& stage = stages[i];
    std::string passes;
    if (local && (stage.passes & kLocalPass)) passes = "local step";
    if (stage.passes & kSubStepPass) {
      passes += passes.empty() ? "sub-steps" : ", sub-steps";
      if (local) passes += " (fallback)";
    }
    const bool needed = stage.needed(c) && !passes.empty();
    out.push_back({std::string(stage.name), std::string(stage.srs_ids),
                   needed ? stage.describe(c) : std::string(), passes, needed, stage_runs_[i],
                   stage_seconds_[i]});
  }
  return out;
}

}  // namespace gp
