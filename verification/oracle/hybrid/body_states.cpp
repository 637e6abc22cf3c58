#include "verification/oracle/hybrid/body_states.hpp"

namespace gp::oracle {

BodyStates::BodyStates(const World& world) : world_(world) {
  for (std::size_t j = 0; j < world.bodies.size(); ++j) {
    if (world.bodies[j].type == BodyType::Dynamic) dynamic_.push_back(j);
  }
}

void BodyStates::initial_values(double* y) const {
  std::vector<Motion> motions;
  for (const RigidBody& b : world_.bodies) motions.push_back(b.initial);
  values_of(motions, y);
}

void BodyStates::motions_at(double t, const double* y, std::span<Motion> motions) const {
  for (std::size_t j = 0; j < world_.bodies.size(); ++j) {
    const RigidBody& b = world_.bodies[j];
    Motion m = b.initial;
    if (b.type == BodyType::Kinematic) {
      m.position += t * m.velocity;
      m.angle += t * m.angular_velocity;
    }
    motions[j] = m;
  }
  for (std::size_t k = 0; k < dynamic_.size(); ++k) {
    const double* p = y + kPerBody * k;
    motions[dynamic_[k]] = {Vec2(p[0], p[1]), p[2], Vec2(p[3], p[4]), p[5]};
  }
}

void BodyStates::values_of(std::span<const Motion> motions, double* y) const {
  for (std::size_t k = 0; k < dynamic_.size(); ++k) {
    const Motion& m = motions[dynamic_[k]];
    double* p = y + kPerBody * k;
    p[0] = m.position.x();
    p[1] = m.position.y();
    p[2] = m.angle;
    p[3] = m.velocity.x();
    p[4] = m.velocity.y();
    p[5] = m.angular_velocity;
  }
}

void BodyStates::derivative_of(std::span<const Motion> motions, std::span<const Vec2> linear,
                               std::span<const double> angular, double* dydt) const {
  for (std::size_t k = 0; k < dynamic_.size(); ++k) {
    const std::size_t j = dynamic_[k];
    double* d = dydt + kPerBody * k;
    d[0] = motions[j].velocity.x();
    d[1] = motions[j].velocity.y();
    d[2] = motions[j].angular_velocity;
    d[3] = linear[j].x();
    d[4] = linear[j].y();
    d[5] = angular[j];
  }
}

}  // namespace gp::oracle
