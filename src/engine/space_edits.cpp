// What a user changes in a space between steps: a body's state, impulses and forces, removal, and
// finding a body by name.
#include <algorithm>
#include <string>

#include "scene/input_error.hpp"
#include "scene/validation.hpp"
#include "engine/space.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/impulse.hpp"
#include "gamephysics/models/dd/torque.hpp"

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
  const std::string field = field_of(body);
  if (types_[body] != BodyType::Dynamic) {
    throw InputError(field + ".type", "must be dynamic to " + what,
                     types_[body] == BodyType::Static ? "static" : "kinematic");
  }
  return field;
}

void Space::set_position(BodyId body, const Vec2& position) {
  validate_finite(position, field_of(body) + ".position");
  state_.position[body] = position;
  // Static shapes are placed once; placed again, with this one where it now is, on the next step.
  world_start_.clear();
  world_end_.clear();
}

void Space::set_angle(BodyId body, double angle) {
  validate_finite(angle, field_of(body) + ".angle");
  state_.angle[body] = dd::rotated_orientation(angle, 0.0);
  world_start_.clear();
  world_end_.clear();
}

void Space::set_velocity(BodyId body, const Vec2& velocity) {
  const std::string field = field_of(body) + ".velocity";
  validate_finite(velocity, field);
  if (types_[body] == BodyType::Static) {
    throw InputError(field, "cannot be set on a static body, which never moves", "static");
  }
  state_.velocity[body] = velocity;
}

void Space::set_angular_velocity(BodyId body, double angular_velocity) {
  const std::string prefix = field_of(body);
  validate_finite(angular_velocity, prefix + ".angular_velocity");
  if (types_[body] == BodyType::Static) {
    throw InputError(prefix + ".angular_velocity",
                     "cannot be set on a static body, which never moves", "static");
  }
  if (types_[body] == BodyType::Dynamic && inertia_.inverse_moment[body] == 0.0 &&
      angular_velocity != 0.0) {
    throw InputError(prefix + ".moment", "is required for a body without area that rotates",
                     "none");
  }
  state_.angular_velocity[body] = angular_velocity;
}

void Space::apply_impulse(BodyId body, const Vec2& impulse, const Vec2& point) {
  const std::string prefix = dynamic_field_of(body, "take an impulse");
  validate_finite(impulse, prefix + ".impulse");
  validate_finite(point, prefix + ".point");
  state_.velocity[body] += dd::velocity_change_from_impulse(impulse, inertia_.inverse_mass[body]);
  // A body that cannot rotate (inverse moment 0) takes no angular impulse.
  state_.angular_velocity[body] +=
      inertia_.inverse_moment[body] * dd::torque(point - state_.position[body], impulse);
}

void Space::apply_force(BodyId body, const Vec2& force, const Vec2& point) {
  const std::string prefix = dynamic_field_of(body, "take a force");
  validate_finite(force, prefix + ".force");
  validate_finite(point, prefix + ".point");
  forces_.add_for_next_step(body, inertia_.inverse_moment[body],
                            {force, dd::torque(point - state_.position[body], force)});
}

void Space::remove_body(BodyId body) {
  field_of(body);
  const BodyShapes::Range gone = shapes_.remove_body(body);
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
    std::erase_if(warm_starts_, [&](const WarmStart& w) {
      const ProxyPair pair = WarmStart::pair_of(w.pair());
      return is_gone(pair.first) || is_gone(pair.second);
    });
    for (WarmStart& w : warm_starts_) {
      const ProxyPair pair = WarmStart::pair_of(w.pair());
      w.key = WarmStart::key_of(WarmStart::pair_key({moved(pair.first), moved(pair.second)}),
                                w.features());
    }
    contacts_.erase_if([body](const Contact& c) { return c.body_a == body || c.body_b == body; });
    for (Contact& c : contacts_) {
      c.shape_a = moved(c.shape_a);
      c.shape_b = moved(c.shape_b);
    }
    --bodies_with_shapes_;
    dynamic_with_shapes_ = false;
    for (std::size_t i = 0; i < shapes_.size(); ++i) {
      dynamic_with_shapes_ = dynamic_with_shapes_ || dynamic_[shapes_[i].body] != 0;
    }
    collides_ = bodies_with_shapes_ >= 2 && dynamic_with_shapes_;
    if (!collides_) contacts_.clear();
    world_start_.clear();
    world_end_.clear();
  }
  std::erase_if(impacts_, [body](const Impact& i) { return i.body_a == body || i.body_b == body; });
  if (dynamic_[body]) forces_.remove(body);
  std::erase(kinematic_, body);
  dynamic_[body] = 0;
  inertia_.inverse_mass[body] = 0.0;
  inertia_.inverse_moment[body] = 0.0;
  state_.velocity[body] = Vec2::Zero();
  state_.angular_velocity[body] = 0.0;
  removed_[body] = 1;
}

std::optional<BodyId> Space::find_body(std::string_view name) const {
  for (BodyId j = 0; j < body_count(); ++j) {
    if (!removed(j) && names_[j] == name) return j;
  }
  return std::nullopt;
}

}  // namespace gp
