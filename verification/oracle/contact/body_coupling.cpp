#include "verification/oracle/contact/body_coupling.hpp"

namespace gp::oracle {

namespace {

Eigen::Vector3d inverse_mass_times(const RigidBody& body, const Eigen::Vector3d& v) {
  return {body.inverse_mass * v.x(), body.inverse_mass * v.y(), body.inverse_moment * v.z()};
}

}  // namespace

double coupling(const World& world, const BodyPairVector& row, const BodyPairVector& column) {
  double sum = 0.0;
  const auto add = [&](std::size_t body, const Eigen::Vector3d& r) {
    if (body == column.first) {
      sum += r.dot(inverse_mass_times(world.bodies[body], column.on_first));
    } else if (body == column.second) {
      sum += r.dot(inverse_mass_times(world.bodies[body], column.on_second));
    }
  };
  add(row.first, row.on_first);
  add(row.second, row.on_second);
  return sum;
}

double dot(const BodyPairVector& row, std::span<const Vec2> linear,
           std::span<const double> angular) {
  const auto part = [&](std::size_t body, const Eigen::Vector3d& r) {
    return r.x() * linear[body].x() + r.y() * linear[body].y() + r.z() * angular[body];
  };
  return part(row.first, row.on_first) + part(row.second, row.on_second);
}

void add_response(const World& world, const BodyPairVector& direction, double magnitude,
                  std::span<Vec2> linear, std::span<double> angular) {
  const auto push = [&](std::size_t body, const Eigen::Vector3d& f) {
    const Eigen::Vector3d change = inverse_mass_times(world.bodies[body], f) * magnitude;
    linear[body] += Vec2(change.x(), change.y());
    angular[body] += change.z();
  };
  push(direction.first, direction.on_first);
  push(direction.second, direction.on_second);
}

}  // namespace gp::oracle
