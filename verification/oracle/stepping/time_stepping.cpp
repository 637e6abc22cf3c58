#include "verification/oracle/stepping/time_stepping.hpp"

#include <algorithm>
#include <cmath>

#include "verification/oracle/stepping/moreau_jean.hpp"

namespace gp::oracle {

SteppedRun time_stepping(const World& world, std::span<const HullPair> pairs,
                         std::span<const double> times, double step, double tolerance) {
  SteppedRun run;
  std::vector<Motion> motions;
  for (const RigidBody& b : world.bodies) motions.push_back(b.initial);
  double t = 0.0;
  for (double t_out : times) {
    // 1e-9 of a step: an interval that is a whole number of steps up to rounding stays one.
    const long count = std::lround(std::ceil((t_out - t) / step - 1e-9));
    const double h = count > 0 ? (t_out - t) / static_cast<double>(count) : 0.0;
    for (long i = 0; i < count; ++i) {
      const std::vector<StepContact> contacts = index_set(world, pairs, motions, h, tolerance);
      for (const StepContact& c : contacts) {
        run.deepest_overlap = std::max(run.deepest_overlap, -c.kinematics.gap);
      }
      moreau_jean_step(world, contacts, h, motions);
      ++run.steps;
    }
    t = t_out;
    run.motions.push_back(motions);
  }
  return run;
}

}  // namespace gp::oracle
