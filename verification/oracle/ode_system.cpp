#include "verification/oracle/ode_system.hpp"

#include "gamephysics/models/dd/angular_velocity.hpp"
#include "gamephysics/models/dd/linear_displacement.hpp"
#include "gamephysics/models/dd/linear_velocity.hpp"

namespace gp::verification {

OdeSystem::OdeSystem(const Space& space)
    : forces_(space.force_model()),
      dynamic_(space.force_model().bodies()),
      t0_(space.time()),
      initial_(space.motion_state()),
      scratch_(space.motion_state()) {
  for (BodyId body = 0; body < space.body_count(); ++body) {
    if (space.type(body) == BodyType::Kinematic) kinematic_.push_back(body);
  }
  acceleration_.resize(space.body_count());
}

void OdeSystem::initial_values(double* y) const {
  values_of(initial_, y);
}

void OdeSystem::state_at(double t, const double* y, MotionState& s) const {
  s = initial_;  // static bodies, and the sizes
  for (std::size_t k = 0; k < dynamic_.size(); ++k) {
    const BodyId j = dynamic_[k];
    const double* yj = y + kPerBody * k;
    s.position[j] = {yj[0], yj[1]};
    s.angle[j] = yj[2];
    s.velocity[j] = {yj[3], yj[4]};
    s.angular_velocity[j] = yj[5];
  }
  const double elapsed = t - t0_;
  for (BodyId j : kinematic_) {
    s.position[j] = dd::displaced_position(
        initial_.position[j], dd::displacement_from_velocity(initial_.velocity[j], elapsed));
    s.angle[j] = initial_.angle[j] +
                 dd::angular_displacement_from_velocity(initial_.angular_velocity[j], elapsed);
  }
}

void OdeSystem::values_of(const MotionState& s, double* y) const {
  for (std::size_t k = 0; k < dynamic_.size(); ++k) {
    const BodyId j = dynamic_[k];
    double* yj = y + kPerBody * k;
    yj[0] = s.position[j].x();
    yj[1] = s.position[j].y();
    yj[2] = s.angle[j];
    yj[3] = s.velocity[j].x();
    yj[4] = s.velocity[j].y();
    yj[5] = s.angular_velocity[j];
  }
}

void OdeSystem::accelerations(double t, const MotionState& s, Accelerations& a) const {
  a.resize(s.position.size());
  forces_.evaluate(t, s, a);
}

void OdeSystem::derivative(double t, const double* y, double* dydt) {
  state_at(t, y, scratch_);
  forces_.evaluate(t, scratch_, acceleration_);
  for (std::size_t k = 0; k < dynamic_.size(); ++k) {
    const BodyId j = dynamic_[k];
    const double* yj = y + kPerBody * k;
    double* fj = dydt + kPerBody * k;
    fj[0] = yj[3];  // dp/dt = v
    fj[1] = yj[4];
    fj[2] = yj[5];  // dϕ/dt = ω
    fj[3] = acceleration_.linear[j].x();
    fj[4] = acceleration_.linear[j].y();
    fj[5] = acceleration_.angular[j];
  }
}

}  // namespace gp::verification
