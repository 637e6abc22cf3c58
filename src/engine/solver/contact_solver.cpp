#include "engine/solver/contact_solver.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "engine/solver/velocity_passes.hpp"
#include "engine/step/step_context.hpp"

namespace gp {

namespace {

PositionLimits position_limits(const Settings& s) {
  return {s.position_iterations, s.linear_slop};
}

}  // namespace

void ContactSolver::prepare(StepContext& c) {
  batches_.build(c.contacts, c.warm_starts, c.inertia, c.start.position,
                 {static_cast<std::size_t>(c.settings.island_part_contacts),
                  static_cast<std::size_t>(c.settings.coloured_island_contacts),
                  static_cast<std::size_t>(c.settings.stored_in_order_contacts),
                  static_cast<std::size_t>(c.settings.island_parts)});
  batches_.store_in_order(c.contacts);
  before_impulses_.take(c.state, positions_.lend_room());
  deepest_ = prepare_and_warm_start(batches_, c.contacts,
                                    {c.shapes, c.inertia, c.start, c.h, c.settings}, c.state);
}

void ContactSolver::solve_small_islands(StepContext& c) {
  const Settings& settings = c.settings;
  // A resting island is held when no point closes faster than a tenth of what gravity adds to
  // it in the step.
  const double unheld_speed = 0.1 * settings.gravity.norm() * c.h;
  // A contact point lies midway between the shapes' surfaces, at most the margin apart or, in an
  // island at rest, the slop deep.
  const double contact_reach =
      c.shapes.moving_reach() + std::max(settings.contact_margin, settings.linear_slop);
  gp::solve_small_islands(
      c.contacts, batches_.islands(), {c.inertia, c.start, c.h, settings.gravity, contact_reach},
      {static_cast<std::size_t>(settings.direct_solve_points),
       static_cast<std::size_t>(settings.direct_solve_uneven_points),
       settings.direct_solve_mass_ratio,
       static_cast<std::size_t>(settings.direct_solve_resting_points), settings.sleep_speed,
       settings.sleep_angular_speed, unheld_speed, settings.linear_slop},
      c.state, islands_);
}

void ContactSolver::solve_velocities(StepContext& c) {
  gp::solve_velocities(batches_, c.contacts, c.inertia,
                       {c.settings.velocity_iterations, c.settings.velocity_tolerance}, c.state);
}

void ContactSolver::apply_restitution(StepContext& c) {
  gp::apply_restitution(batches_, c.contacts, c.inertia, c.state);
}

void ContactSolver::move_by_impulses(StepContext& c) {
  move_by_velocity_changes(before_impulses_, c.integrator->impulse_position_share() * c.h, c.state);
  positions_.take_room(before_impulses_.release());
}

void ContactSolver::solve_speculative(StepContext& c) {
  gp::solve_speculative(c, batches_.stored_at(), speculative_);
  positions_.correct(c.speculative_contacts, {c.shapes, c.inertia, c.start},
                     position_limits(c.settings), c.state);
  c.speculative_contacts.clear();
}

void ContactSolver::correct_positions(StepContext& c) {
  const ContactGeometry geometry{c.shapes, c.inertia, c.start};
  const PositionLimits limits = position_limits(c.settings);
  // Read once: a later sub-step's contacts have a deepest of their own.
  const double deepest = std::exchange(deepest_, std::numeric_limits<double>::infinity());
  if (surely_within_slop(deepest, c.settings.contact_margin, geometry, limits, c.state)) return;
  positions_.correct(batches_, c.contacts, geometry, limits, c.state);
}

void ContactSolver::restore_order(StepContext& c) {
  batches_.restore_order(c.contacts);
}

}  // namespace gp
