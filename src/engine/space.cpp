#include "engine/space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/capacity.hpp"
#include "engine/geometry/transform.hpp"
#include "engine/numerical_error.hpp"
#include "engine/setup/mass_setup.hpp"
#include "engine/setup/mass_validation.hpp"
#include "engine/setup/shape_offset.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/angular_velocity.hpp"
#include "gamephysics/models/dd/linear_displacement.hpp"
#include "gamephysics/models/dd/linear_velocity.hpp"
#include "scene/input_error.hpp"
#include "scene/validation.hpp"

namespace gp {

Space::Space(const Settings& settings)
    : settings_((validate_settings(settings), settings)),
      forces_(settings),
      integrator_(make_integrator(settings.integrator)),
      detection_(settings.contact_margin) {}

Space::~Space() = default;

BodyId Space::add_body(const BodyDef& def) {
  const auto id = static_cast<BodyId>(names_.size());
  const std::string prefix = "bodies[" + std::to_string(id) + "]";
  validate_body(def, prefix);
  validate_derived_mass(def, prefix);
  const MassSetup mass = mass_setup(def);
  const bool dynamic = def.type == BodyType::Dynamic;
  const bool rotates = dynamic && mass.moment > 0.0;
  if (dynamic && !rotates && (def.angular_velocity != 0.0 || def.torque != 0.0)) {
    throw InputError(prefix + ".moment", "is required for a body without area that rotates",
                     "none");
  }
  // Checked before anything is added, so that a body that cannot be added leaves no part behind.
  if (def.shapes.size() > BodyShapes::kMaxShapes - shapes_.size()) {
    throw InputError(prefix + ".shapes", "at most 2^24 shapes in a space (warm starts' keys)",
                     std::to_string(shapes_.size() + def.shapes.size()) + " in all");
  }
  names_.add(def.name);
  append(types_, def.type);
  append(dynamic_, dynamic);
  append(removed_, char{0});
  append(inertia_.inverse_mass, dynamic ? 1.0 / mass.mass : 0.0);
  append(inertia_.inverse_moment, rotates ? 1.0 / mass.moment : 0.0);
  const Transform frame(def.position, def.angle);
  append(state_.position, frame.apply(mass.local_center));
  append(state_.angle, dd::rotated_orientation(def.angle, 0.0));
  append(state_.velocity, def.type == BodyType::Static ? Vec2::Zero() : def.velocity);
  append(state_.angular_velocity, def.type == BodyType::Static ? 0.0 : def.angular_velocity);
  if (dynamic) {
    forces_.add(id, {mass.mass, inertia_.inverse_moment.back(), def.force, def.torque,
                     def.force_point.has_value(),
                     def.force_point.value_or(mass.local_center) - mass.local_center, nullptr});
  }
  if (def.type == BodyType::Kinematic) kinematic_.push_back(id);
  for (const ShapeDef& s : def.shapes) {
    shapes_.add(id, translated(s.shape, -mass.local_center), s.restitution, s.friction,
                def.type != BodyType::Static);
  }
  if (!def.shapes.empty()) {
    ++bodies_with_shapes_;
    dynamic_with_shapes_ = dynamic_with_shapes_ || dynamic;
    collides_ = bodies_with_shapes_ >= 2 && dynamic_with_shapes_;
  }
  world_start_.clear();  // the static shapes are placed again on the next step
  return id;
}

void Space::set_force_callback(BodyId body, ForceCallback callback) {
  forces_.set_callback(body, inertia_.inverse_moment[body], std::move(callback));
}

double Space::mass(BodyId body) const {
  const double inverse = inertia_.inverse_mass[body];
  return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
}

double Space::moment(BodyId body) const {
  const double inverse = inertia_.inverse_moment[body];
  return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
}

BodyState Space::state(BodyId body) const {
  return state_.of(body);
}

void Space::step(double dt) {
  validate_step(dt, "dt");
  impacts_.clear();
  impacts_this_step_ = 0;
  // Local impacts need ballistic paths that the integrator follows exactly.
  const bool local =
      collides_ && forces_.constant() && integrator_->exact_for_constant_acceleration();
  if (!local || !local_step(dt)) {
    impacts_.clear();
    impacts_this_step_ = 0;
    double remaining = dt;
    // Each sub-step ends at an impact or at the end of the step; impacts are bounded per step.
    while (remaining > 0.0) remaining -= substep(remaining);
  }
  forces_.end_step();
  for (BodyId j : forces_.bodies()) {
    if (!state_.position[j].allFinite() || !state_.velocity[j].allFinite() ||
        !std::isfinite(state_.angle[j]) || !std::isfinite(state_.angular_velocity[j])) {
      throw NumericalError(std::string(names_[j]), time_);
    }
  }
}

void Space::move_kinematic(double h) {
  for (BodyId k : kinematic_) {
    state_.position[k] = dd::displaced_position(
        state_.position[k], dd::displacement_from_velocity(state_.velocity[k], h));
    state_.angle[k] = dd::rotated_orientation(
        state_.angle[k], dd::angular_displacement_from_velocity(state_.angular_velocity[k], h));
  }
}

const std::vector<ProxyPair>& Space::sweep(double h, const Ballistic& motion) {
  shapes_.place(start_.position, start_.angle, world_start_);
  // Boxes swept along the ballistic path catch a fast body wherever it is during the step. The
  // path covers every body: kinematic and static ones have no acceleration, so it ends where
  // move_kinematic moves them, and static ones where they are.
  shapes_.place([&](BodyId j) { return std::pair(motion.position(j, h), motion.angle(j, h)); },
                world_end_);
  return detection_.candidate_pairs(shapes_, dynamic_, world_start_, world_end_);
}

Ballistic Space::start_motion() {
  if (forces_.constant()) return {start_, StepAccelerations(forces_, dynamic_)};
  varying_acceleration_.resize(state_.position.size());
  forces_.evaluate(time_, start_, varying_acceleration_);
  return {start_, StepAccelerations(varying_acceleration_)};
}

double Space::warm_start_scale(double h) const {
  // Resting impulses grow with the step, so they carry over scaled by h / h_prev; never scaled
  // up, because after a short sub-step (an impact) they hold what stopped the impact, which
  // does not grow with the step.
  return previous_h_ > 0.0 ? std::min(1.0, h / previous_h_) : 0.0;
}

bool Space::local_step(double h) {
  start_ = state_;
  const Ballistic motion = start_motion();
  const std::vector<ProxyPair>& pairs = sweep(h, motion);
  detection_.find_contacts(pairs, shapes_, world_start_, start_, warm_starts_, warm_start_scale(h),
                           contacts_);
  local_impacts_.classify(pairs, world_start_, world_end_, motion, h,
                          impacts_this_step_ < settings_.max_impacts_per_step, contacts_);
  local_impacts_.hand_over(world_start_, start_, h, contacts_, speculative_contacts_);
  if (!local_impacts_.resolve(time_, h, start_, motion.acceleration, world_start_, world_end_,
                              contacts_, impacts_this_step_, impacts_)) {
    return false;
  }
  state_ = start_;
  advance(h);
  return true;
}

double Space::substep(double h) {
  start_ = state_;
  const std::vector<ProxyPair>* impact_pairs = nullptr;
  if (collides_) {
    const Ballistic motion = start_motion();
    const auto& pairs = sweep(h, motion);
    contact_pairs_.assign(pairs.begin(), pairs.end());
    if (impacts_this_step_ < settings_.max_impacts_per_step) {
      const auto tau = impact_search_.earliest(contact_pairs_, shapes_, world_start_, world_end_,
                                               motion, h, impact_filter(settings_));
      if (tau && *tau < h) {
        h = *tau;
        impact_pairs = &impact_search_.touching();
        // The impact pairs are resolved exactly at t_c; their gap must not be closed by the
        // contact solver before it.
        std::erase_if(contact_pairs_, [impact_pairs](const ProxyPair& p) {
          return std::find(impact_pairs->begin(), impact_pairs->end(), p) != impact_pairs->end();
        });
      }
    }
    detection_.find_contacts(contact_pairs_, shapes_, world_start_, start_, warm_starts_,
                             warm_start_scale(h), contacts_);
  }
  advance(h);
  if (impact_pairs) {
    resolve_impacts(*impact_pairs, shapes_, inertia_, settings_, time_, state_, impact_scratch_,
                    impacts_);
    ++impacts_this_step_;
  }
  return h;
}

void Space::advance(double h) {
  // Impacts among touching bodies happen at the start of the step, before its forces.
  if (!contacts_.empty() && propagate_impacts(contacts_, shapes_, inertia_, settings_, state_)) {
    start_.velocity = state_.velocity;
    start_.angular_velocity = state_.angular_velocity;
  }
  integrator_->advance(forces_, time_, h, state_);
  move_kinematic(h);
  if (!contacts_.empty()) {
    prepare_contacts(contacts_, shapes_, inertia_, start_, h, settings_);
    warm_start(contacts_, inertia_, state_);
    solve_small_islands(contacts_, inertia_, settings_.direct_solve_points, state_,
                        island_scratch_);
    solve_velocities(contacts_, inertia_, settings_.velocity_iterations,
                     settings_.velocity_tolerance, state_);
    apply_restitution(contacts_, inertia_, state_);
    move_by_contact_impulses(contacts_, inertia_, integrator_->impulse_position_share() * h,
                             state_);
  }
  if (!speculative_contacts_.empty()) {
    solve_speculative(contacts_, speculative_contacts_, shapes_, inertia_, start_, h, settings_,
                      state_, speculative_scratch_);
    correct_positions(speculative_contacts_, shapes_, inertia_, start_.angle,
                      settings_.position_iterations, settings_.linear_slop, state_, rotations_);
    speculative_contacts_.clear();
  }
  if (!contacts_.empty()) {
    correct_positions(contacts_, shapes_, inertia_, start_.angle, settings_.position_iterations,
                      settings_.linear_slop, state_, rotations_);
  }
  time_ += h;
  keep_impulses(contacts_, warm_starts_);
  previous_h_ = h;
}

}  // namespace gp
