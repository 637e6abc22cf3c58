// What a user changes in a space between steps: a body's state, impulses and forces, removal, and
// finding a body by name.
#include <algorithm>
#include <string>

#include "engine/sleep/sleeping.hpp"
#include "engine/space.hpp"
#include "engine/space_impl.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/impulse.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "scene/input_error.hpp"
#include "scene/validation.hpp"

namespace gp {

std::string Space::field_of(BodyId body) const {
  const std::string field = "bodies[" + std::to_string(body) + "]";
  if (body >= body_count()) {
    throw InputError(field, "must be a body of the space",
                     "no such body (" + std::to_string(body_count()) + " bodies)");
  }
  if (removed(body)) throw InputError(field, "must be a body of the space", "a removed body");
  return field;
}

std::string Space::dynamic_field_of(BodyId body, const std::string& what) const {
  Impl& self = *impl_;
  const std::string field = field_of(body);
  if (self.types[body] != BodyType::Dynamic) {
    throw InputError(field + ".type", "must be dynamic to " + what,
                     self.types[body] == BodyType::Static ? "static" : "kinematic");
  }
  return field;
}

void Space::set_position(BodyId body, const Vec2& position) {
  Impl& self = *impl_;
  StepContext& c = self.context;
  validate_finite(position, field_of(body) + ".position");
  wake_island(c, body);
  c.state.position[body] = position;
  // Static shapes are placed once; placed again, with this one where it now is, on the next step.
  c.world_start.clear();
  c.end_bounds.clear();
}

void Space::set_angle(BodyId body, double angle) {
  Impl& self = *impl_;
  StepContext& c = self.context;
  validate_finite(angle, field_of(body) + ".angle");
  wake_island(c, body);
  c.state.angle[body] = dd::rotated_orientation(angle, 0.0);
  c.world_start.clear();
  c.end_bounds.clear();
}

void Space::set_velocity(BodyId body, const Vec2& velocity) {
  Impl& self = *impl_;
  StepContext& c = self.context;
  const std::string field = field_of(body) + ".velocity";
  validate_finite(velocity, field);
  if (self.types[body] == BodyType::Static) {
    throw InputError(field, "cannot be set on a static body, which never moves", "static");
  }
  wake_island(c, body);
  c.state.velocity[body] = velocity;
}

void Space::set_angular_velocity(BodyId body, double angular_velocity) {
  Impl& self = *impl_;
  StepContext& c = self.context;
  const std::string prefix = field_of(body);
  validate_finite(angular_velocity, prefix + ".angular_velocity");
  if (self.types[body] == BodyType::Static) {
    throw InputError(prefix + ".angular_velocity",
                     "cannot be set on a static body, which never moves", "static");
  }
  if (self.types[body] == BodyType::Dynamic && c.inertia.inverse_moment[body] == 0.0 &&
      angular_velocity != 0.0) {
    throw InputError(prefix + ".moment", "is required for a body without area that rotates",
                     "none");
  }
  wake_island(c, body);
  c.state.angular_velocity[body] = angular_velocity;
}

void Space::apply_impulse(BodyId body, const Vec2& impulse, const Vec2& point) {
  Impl& self = *impl_;
  StepContext& c = self.context;
  const std::string prefix = dynamic_field_of(body, "take an impulse");
  validate_finite(impulse, prefix + ".impulse");
  validate_finite(point, prefix + ".point");
  wake_island(c, body);
  c.state.velocity[body] += dd::velocity_change_from_impulse(impulse, c.inertia.inverse_mass[body]);
  // A body that cannot rotate (inverse moment 0) takes no angular impulse.
  c.state.angular_velocity[body] +=
      c.inertia.inverse_moment[body] * dd::torque(point - c.state.position[body], impulse);
}

void Space::apply_force(BodyId body, const Vec2& force, const Vec2& point) {
  Impl& self = *impl_;
  StepContext& c = self.context;
  const std::string prefix = dynamic_field_of(body, "take a force");
  validate_finite(force, prefix + ".force");
  validate_finite(point, prefix + ".point");
  wake_island(c, body);
  c.forces.add_for_next_step(body, c.inertia.inverse_moment[body],
                             {force, dd::torque(point - c.state.position[body], force)});
}

void Space::remove_body(BodyId body) {
  Impl& self = *impl_;
  StepContext& c = self.context;
  field_of(body);
  wake_island(c, body);
  const BodyShapes::Range gone = c.shapes.remove_body(body);
  if (gone.last > gone.first) {
    // Shape indices after the removed ones move down; pairs with a removed shape are dropped.
    const std::uint32_t count = gone.last - gone.first;
    const auto is_gone = [gone](std::uint32_t shape) {
      return shape >= gone.first && shape < gone.last;
    };
    const auto moved = [gone, count](std::uint32_t shape) {
      return shape >= gone.last ? shape - count : shape;
    };
    // The warm starts stay sorted: the indices move down monotonically.
    std::erase_if(c.warm_starts, [&](const WarmStart& w) {
      const ShapePair pair = WarmStart::pair_of(w.pair());
      return is_gone(pair.first) || is_gone(pair.second);
    });
    for (WarmStart& w : c.warm_starts) {
      const ShapePair pair = WarmStart::pair_of(w.pair());
      w.key = WarmStart::point_key(WarmStart::pair_key({moved(pair.first), moved(pair.second)}),
                                   w.features());
    }
    c.contacts.erase_if([body](const Contact& c) { return c.body_a == body || c.body_b == body; });
    for (Contact& c : c.contacts) {
      c.shape_a = moved(c.shape_a);
      c.shape_b = moved(c.shape_b);
    }
    --self.bodies_with_shapes;
    self.dynamic_with_shapes = false;
    for (std::size_t i = 0; i < c.shapes.size(); ++i) {
      self.dynamic_with_shapes = self.dynamic_with_shapes || c.dynamic[c.shapes[i].body] != 0;
    }
    c.collides = self.bodies_with_shapes >= 2 && self.dynamic_with_shapes;
    if (!c.collides) {
      c.contacts.clear();
      c.warm_starts.clear();
    }
    c.world_start.clear();
    c.end_bounds.clear();
  }
  std::erase_if(c.impacts,
                [body](const Impact& i) { return i.body_a == body || i.body_b == body; });
  if (c.dynamic[body]) c.forces.remove(body);
  std::erase(c.kinematic, body);
  c.dynamic[body] = 0;
  c.inertia.inverse_mass[body] = 0.0;
  c.inertia.inverse_moment[body] = 0.0;
  c.state.velocity[body] = Vec2::Zero();
  c.state.angular_velocity[body] = 0.0;
  self.removed[body] = 1;
}

std::optional<BodyId> Space::find_body(std::string_view name) const {
  Impl& self = *impl_;
  for (BodyId j = 0; j < body_count(); ++j) {
    if (!removed(j) && self.names[j] == name) return j;
  }
  return std::nullopt;
}

}  // namespace gp
