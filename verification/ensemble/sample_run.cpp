#include "verification/ensemble/sample_run.hpp"

#include <algorithm>
#include <exception>

#include <tbb/task_arena.h>

#include "engine/output/output_times.hpp"
#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "verification/oracle/oracle.hpp"
#include "verification/quantities/mechanical_quantities.hpp"
#include "verification/suite/oracle_domain.hpp"

namespace gp::verification {

namespace {

OracleComparison compare_with_oracle(const Scene& scene, const std::vector<double>& times,
                                     const std::vector<std::vector<BodyState>>& engine) {
  OracleComparison c;
  try {
    const OracleResult oracle = run_oracle(scene, times, reference_options(scene));
    for (std::size_t k = 0; k < times.size(); ++k) {
      for (std::size_t b = 0; b < engine[k].size(); ++b) {
        const BodyState& ours = engine[k][b];
        const BodyState& theirs = oracle.states[k][b];
        c.position_error = std::max(c.position_error, (ours.position - theirs.position).norm());
        c.velocity_error = std::max(c.velocity_error, (ours.velocity - theirs.velocity).norm());
      }
    }
    c.status = "ok";
  } catch (const std::exception& e) {  // OracleDomainError: the sample left the oracle's domain
    c.status = e.what();
  }
  return c;
}

SampleOutputs run_alone(const Scene& scene, bool with_oracle) {
  SampleOutputs out;
  std::vector<double> times;
  std::vector<std::vector<BodyState>> states;  // kept only for the oracle's comparison
  try {
    const auto space = build_space(scene);
    run_steps(
        scene,
        [&](double dt) {
          space->step(dt);
          for (const Impact& impact : space->impacts()) {
            if (out.impact_times.size() < kRecordedImpacts) out.impact_times.push_back(impact.time);
            ++out.impact_count;
          }
        },
        [&](double t) {
          out.energy.push_back(invariants(*space).energy());
          out.final_states.clear();
          for (BodyId b = 0; b < space->body_count(); ++b)
            out.final_states.push_back(space->state(b));
          if (with_oracle) {
            times.push_back(t);
            states.push_back(out.final_states);
          }
        });
  } catch (const std::exception& e) {  // NumericalError, or an input the SRS constraints refuse
    out.error = e.what();
    return out;
  }
  if (with_oracle) out.oracle = compare_with_oracle(scene, times, states);
  return out;
}

}  // namespace

SampleOutputs run_sample(const Scene& scene, bool with_oracle) {
  // The samples are the parallel work: each steps on one thread, in an arena of its own per
  // worker, rather than splitting its steps across workers that other samples keep busy.
  thread_local tbb::task_arena alone(1);
  return alone.execute([&] { return run_alone(scene, with_oracle); });
}

}  // namespace gp::verification
