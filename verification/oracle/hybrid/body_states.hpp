#pragma once
// The oracle's state vector: x, y, ϕ, vx, vy, ω of every dynamic body, in the world's body order.
// Kinematic bodies are not in it (they move at constant velocity, in closed form), nor static ones.

#include <cstddef>
#include <span>
#include <vector>

#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

class BodyStates {
 public:
  /// Components of y per dynamic body.
  static constexpr std::size_t kPerBody = 6;

  /// `world` must outlive this.
  explicit BodyStates(const World& world);

  std::size_t size() const { return kPerBody * dynamic_.size(); }
  std::size_t body_count() const { return world_.bodies.size(); }

  /// y at t = 0.
  void initial_values(double* y) const;
  /// Every body's motion at time t [s] (one entry per body of the world): the dynamic ones from
  /// y, the kinematic ones from their constant velocities, the static ones where they are.
  void motions_at(double t, const double* y, std::span<Motion> motions) const;
  /// y from the dynamic bodies of `motions`.
  void values_of(std::span<const Motion> motions, double* y) const;
  /// dy/dt from the motions and the accelerations of every body.
  void derivative_of(std::span<const Motion> motions, std::span<const Vec2> linear,
                     std::span<const double> angular, double* dydt) const;

 private:
  const World& world_;
  std::vector<std::size_t> dynamic_;
};

}  // namespace gp::oracle
