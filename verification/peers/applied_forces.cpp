#include "verification/peers/applied_forces.hpp"

#include "engine/geometry/transform.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/gd/gravitational_acceleration.hpp"

namespace gp::peers {

AppliedForces::AppliedForces(const PeerScene& scene) : G_(scene.G) {
  for (BodyId id = 0; id < scene.bodies.size(); ++id) {
    const PeerBody& b = scene.bodies[id];
    if (b.type != BodyType::Dynamic) continue;
    if (G_) {
      attractors_.push_back(id);
      attractor_mass_.push_back(b.mass);
    }
    if (G_ || b.force != Vec2::Zero() || b.torque != 0.0) {
      sources_.push_back({id, b.mass, b.force, b.torque, b.arm});
      needs_states_ |= b.arm.has_value();
    }
  }
  needs_states_ |= G_.has_value();
  wrenches_.resize(sources_.size());
}

const std::vector<BodyWrench>& AppliedForces::evaluate(const std::vector<BodyState>& states) {
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    const Source& s = sources_[k];
    Wrench w{s.force, s.torque};
    if (s.arm) {
      w.torque += dd::torque(Transform(Vec2::Zero(), states[s.body].angle).rotate(*s.arm), s.force);
    }
    if (G_) {
      Vec2 g = Vec2::Zero();
      for (std::size_t i = 0; i < attractors_.size(); ++i) {
        const BodyId other = attractors_[i];
        if (other == s.body) continue;
        g += gd::gravitational_acceleration(*G_, attractor_mass_[i],
                                            states[s.body].position - states[other].position);
      }
      w.force += s.mass * g;
    }
    wrenches_[k] = {s.body, w};
  }
  return wrenches_;
}

}  // namespace gp::peers
