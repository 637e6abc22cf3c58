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
#include "engine/sleep/sleeping.hpp"
#include "engine/space_impl.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "scene/input_error.hpp"
#include "scene/validation.hpp"

namespace gp {

Space::Space(const Settings& settings)
    : impl_(std::make_unique<Impl>((validate_settings(settings), settings))) {}

Space::~Space() = default;

BodyId Space::add_body(const BodyDef& def) {
  Impl& self = *impl_;
  StepContext& c = self.context;
  const auto id = static_cast<BodyId>(self.names.size());
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
  if (def.shapes.size() > BodyShapes::kMaxShapes - c.shapes.size()) {
    throw InputError(prefix + ".shapes", "at most 2^24 shapes in a space (warm starts' keys)",
                     std::to_string(c.shapes.size() + def.shapes.size()) + " in all");
  }
  self.names.add(def.name);
  append(self.types, def.type);
  append(c.dynamic, dynamic);
  append(self.removed, char{0});
  append(c.inertia.inverse_mass, dynamic ? 1.0 / mass.mass : 0.0);
  append(c.inertia.inverse_moment, rotates ? 1.0 / mass.moment : 0.0);
  // Only a space that sleeps keeps its bodies' sleep: 29 bytes a body that others do not hold.
  if (c.settings.sleep) {
    append(c.asleep_inertia.inverse_mass, 0.0);
    append(c.asleep_inertia.inverse_moment, 0.0);
    append(c.still_for, 0.0);
    append(c.sleep_island, kAwake);
    append(c.placed_asleep, char{0});
  }
  const Transform frame(def.position, def.angle);
  append(c.state.position, frame.apply(mass.local_center));
  append(c.state.angle, dd::rotated_orientation(def.angle, 0.0));
  append(c.state.velocity, def.type == BodyType::Static ? Vec2::Zero() : def.velocity);
  append(c.state.angular_velocity, def.type == BodyType::Static ? 0.0 : def.angular_velocity);
  if (dynamic) {
    c.forces.add(id, {mass.mass, c.inertia.inverse_moment.back(), def.force, def.torque,
                      def.force_point.has_value(),
                      def.force_point.value_or(mass.local_center) - mass.local_center, nullptr});
  }
  if (def.type == BodyType::Kinematic) c.kinematic.push_back(id);
  for (const ShapeDef& s : def.shapes) {
    c.shapes.add(id, translated(s.shape, -mass.local_center), s.restitution, s.friction,
                 def.type != BodyType::Static);
  }
  if (!def.shapes.empty()) {
    ++self.bodies_with_shapes;
    self.dynamic_with_shapes = self.dynamic_with_shapes || dynamic;
    c.collides = self.bodies_with_shapes >= 2 && self.dynamic_with_shapes;
  }
  c.world_start.clear();  // the static shapes are placed again on the next step
  return id;
}

void Space::set_force_callback(BodyId body, ForceCallback callback) {
  StepContext& c = impl_->context;
  wake_island(c, body);
  c.forces.set_callback(body, c.inertia.inverse_moment[body], std::move(callback));
}

double Space::mass(BodyId body) const {
  const double inverse = impl_->context.inertia.inverse_mass[body];
  return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
}

double Space::moment(BodyId body) const {
  const double inverse = impl_->context.inertia.inverse_moment[body];
  return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
}

BodyState Space::state(BodyId body) const {
  return impl_->context.state.of(body);
}

void Space::step(double dt) {
  validate_step(dt, "dt");
  StepContext& c = impl_->context;
  impl_->runner.step(c, dt);
  c.forces.end_step();
  for (BodyId j : c.forces.bodies()) {
    if (!c.state.position[j].allFinite() || !c.state.velocity[j].allFinite() ||
        !std::isfinite(c.state.angle[j]) || !std::isfinite(c.state.angular_velocity[j])) {
      throw NumericalError(std::string(impl_->names[j]), c.time);
    }
  }
}

bool Space::removed(BodyId body) const {
  return impl_->removed[body] != 0;
}
double Space::time() const {
  return impl_->context.time;
}
std::size_t Space::body_count() const {
  return impl_->names.size();
}
std::string_view Space::name(BodyId body) const {
  return impl_->names[body];
}
BodyType Space::type(BodyId body) const {
  return impl_->types[body];
}
const Settings& Space::settings() const {
  return impl_->context.settings;
}
const std::vector<Impact>& Space::impacts() const {
  return impl_->context.impacts;
}

std::vector<PipelineStage> Space::pipeline() const {
  return impl_->runner.pipeline(impl_->context);
}

void Space::time_stages(bool on) {
  impl_->runner.time_stages(on);
}

std::vector<ContactPointReport> Space::contact_points() const {
  const StepContext& c = impl_->context;
  std::vector<ContactPointReport> points;
  for (const Contact& contact : c.contacts) {
    const Vec2 position_a = c.state.position[contact.body_a];
    for (const ContactPointState& p : c.contacts.points(contact)) {
      points.push_back({contact.body_a, contact.body_b, position_a + arm_a(contact, p),
                        contact.normal, p.normal_impulse, p.tangent_impulse});
    }
  }
  return points;
}

}  // namespace gp
