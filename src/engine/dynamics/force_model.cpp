#include "engine/dynamics/force_model.hpp"

#include <algorithm>

#include "engine/geometry/transform.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/gd/gravitational_acceleration.hpp"
#include "gamephysics/models/im/rotational_motion.hpp"
#include "gamephysics/models/im/translational_motion.hpp"

namespace gp {

void ForceModel::add(BodyId id, BodyForces forces) {
  ids_.push_back(id);
  rotates_.push_back(forces.inverse_moment > 0.0);
  forces_.push_back(std::move(forces));
}

void ForceModel::set_callback(BodyId id, ForceCallback callback) {
  const auto it = std::find(ids_.begin(), ids_.end(), id);
  if (it != ids_.end()) forces_[it - ids_.begin()].callback = std::move(callback);
}

bool ForceModel::constant() const {
  if (G_) return false;
  return std::none_of(forces_.begin(), forces_.end(),
                      [](const BodyForces& f) { return f.force_at_point || f.callback; });
}

bool ForceModel::any_applied() const {
  return std::any_of(forces_.begin(), forces_.end(), [](const BodyForces& f) {
    return f.force != Vec2::Zero() || f.torque != 0.0 || f.callback;
  });
}

void ForceModel::evaluate(double t, const MotionState& s, Accelerations& out) const {
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    const BodyId j = ids_[k];
    const BodyForces& f = forces_[k];
    Vec2 force = f.force;
    double torque = f.torque;
    if (f.force_at_point) {
      // The point turns with the body, so its arm, and the torque, change with ϕ.
      torque += dd::torque(Transform(Vec2::Zero(), s.angle[j]).rotate(f.arm), f.force);
    }
    if (f.callback) {
      const Wrench w =
          f.callback(t, j, {s.position[j], s.angle[j], s.velocity[j], s.angular_velocity[j]});
      force += w.force;
      torque += w.torque;
    }
    Vec2 g = gravity_;
    if (G_) {
      for (std::size_t other = 0; other < ids_.size(); ++other) {
        if (other == k) continue;
        const BodyId i = ids_[other];
        g +=
            gd::gravitational_acceleration(*G_, forces_[other].mass, s.position[j] - s.position[i]);
      }
    }
    out.linear[j] = im::translational_acceleration(g, force, f.mass);
    out.angular[j] = rotates_[k] ? im::angular_acceleration(torque, 1.0 / f.inverse_moment) : 0.0;
  }
}

}  // namespace gp
