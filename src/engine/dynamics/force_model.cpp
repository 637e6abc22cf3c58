#include "engine/dynamics/force_model.hpp"

#include <algorithm>

#include "engine/capacity.hpp"
#include "engine/geometry/transform.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/gd/gravitational_acceleration.hpp"
#include "gamephysics/models/im/rotational_motion.hpp"
#include "gamephysics/models/im/translational_motion.hpp"

namespace gp {

ForceModel::ForceModel(const Settings& settings)
    : gravity_(settings.gravity),
      // No force: the same for every mass.
      falling_(im::translational_acceleration(settings.gravity, Vec2::Zero(), 1.0)),
      G_(settings.G) {}

bool ForceModel::beyond_gravity(const BodyForces& forces) {
  return forces.force != Vec2::Zero() || forces.torque != 0.0 || forces.force_at_point ||
         forces.callback;
}

void ForceModel::add(BodyId id, BodyForces forces) {
  const auto entry = static_cast<std::uint32_t>(ids_.size());
  append(ids_, id);
  append(masses_, forces.mass);
  append(rotates_, forces.inverse_moment > 0.0);
  if (!beyond_gravity(forces)) return;
  // As evaluate() has them when the forces are constant.
  pushed_.push_back({id, im::translational_acceleration(gravity_, forces.force, forces.mass),
                     rotates_.back()
                         ? im::angular_acceleration(forces.torque, 1.0 / forces.inverse_moment)
                         : 0.0});
  applied_.push_back({entry, std::move(forces)});
}

void ForceModel::set_callback(BodyId id, double inverse_moment, ForceCallback callback) {
  const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
  if (it == ids_.end() || *it != id) return;
  const auto entry = static_cast<std::uint32_t>(it - ids_.begin());
  auto at = std::lower_bound(applied_.begin(), applied_.end(), entry,
                             [](const Applied& a, std::uint32_t e) { return a.entry < e; });
  if (at == applied_.end() || at->entry != entry) {
    // A body of gravity only so far: its constant forces are none.
    at = applied_.insert(
        at,
        {entry, {masses_[entry], inverse_moment, Vec2::Zero(), 0.0, false, Vec2::Zero(), nullptr}});
  }
  at->forces.callback = std::move(callback);
}

bool ForceModel::constant() const {
  if (G_) return false;
  return std::none_of(applied_.begin(), applied_.end(), [](const Applied& a) {
    return a.forces.force_at_point || a.forces.callback;
  });
}

bool ForceModel::any_applied() const {
  return std::any_of(applied_.begin(), applied_.end(), [](const Applied& a) {
    return a.forces.force != Vec2::Zero() || a.forces.torque != 0.0 || a.forces.callback;
  });
}

void ForceModel::evaluate(double t, const MotionState& s, Accelerations& out) const {
  auto applied = applied_.begin();
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    const BodyId j = ids_[k];
    Vec2 g = gravity_;
    if (G_) {
      for (std::size_t other = 0; other < ids_.size(); ++other) {
        if (other == k) continue;
        const BodyId i = ids_[other];
        g += gd::gravitational_acceleration(*G_, masses_[other], s.position[j] - s.position[i]);
      }
    }
    if (applied == applied_.end() || applied->entry != k) {
      out.linear[j] = im::translational_acceleration(g, Vec2::Zero(), masses_[k]);
      out.angular[j] = 0.0;
      continue;
    }
    const BodyForces& f = (applied++)->forces;
    Vec2 force = f.force;
    double torque = f.torque;
    if (f.force_at_point) {
      // The point turns with the body, so its arm, and the torque, change with ϕ.
      torque += dd::torque(Transform(Vec2::Zero(), s.angle[j]).rotate(f.arm), f.force);
    }
    if (f.callback) {
      const Wrench w = f.callback(t, j, s.of(j));
      force += w.force;
      torque += w.torque;
    }
    out.linear[j] = im::translational_acceleration(g, force, masses_[k]);
    out.angular[j] = rotates_[k] ? im::angular_acceleration(torque, 1.0 / f.inverse_moment) : 0.0;
  }
}

}  // namespace gp
