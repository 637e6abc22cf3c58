#include <cstddef>

#include "engine/dynamics/integrator.hpp"
#include "gamephysics/models/dd/angular_acceleration.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/angular_velocity.hpp"
#include "gamephysics/models/dd/linear_acceleration.hpp"
#include "gamephysics/models/dd/linear_displacement.hpp"
#include "gamephysics/models/dd/linear_velocity.hpp"

namespace gp {

namespace {

// Moves body j over h with mean velocities v̄, ω̄ (DD:linVel, DD:linDisp, DD:angVel, DD:angDisp).
void move(MotionState& s, BodyId j, bool rotates, const Vec2& mean_velocity,
          double mean_angular_velocity, double h) {
  s.position[j] =
      dd::displaced_position(s.position[j], dd::displacement_from_velocity(mean_velocity, h));
  if (rotates) {
    s.angle[j] = dd::rotated_orientation(
        s.angle[j], dd::angular_displacement_from_velocity(mean_angular_velocity, h));
  }
}

// Changes body j's velocities by mean accelerations over h (DD:linAcc, DD:angAccel).
void accelerate(MotionState& s, BodyId j, bool rotates, const Vec2& mean_acceleration,
                double mean_angular_acceleration, double h) {
  s.velocity[j] += dd::velocity_change_from_acceleration(mean_acceleration, h);
  if (rotates) {
    s.angular_velocity[j] +=
        dd::angular_velocity_change_from_acceleration(mean_angular_acceleration, h);
  }
}

// Moves body j over h along the parabola of a constant acceleration a, α from its velocities, and
// changes them by a h, α h: x₁ = x₀ + (v₀ + a h/2) h, v₁ = v₀ + a h, and the same for ϕ and ω.
void follow_parabola(MotionState& s, BodyId j, bool rotates, const Vec2& a, double alpha,
                     double h) {
  move(s, j, rotates, s.velocity[j] + 0.5 * h * a, s.angular_velocity[j] + 0.5 * h * alpha, h);
  accelerate(s, j, rotates, a, alpha, h);
}

// The accelerations at time t in state s, evaluated into `out` (sized for the bodies of s).
const Accelerations& evaluated(const ForceModel& forces, double t, const MotionState& s,
                               Accelerations& out) {
  out.resize(s.position.size());
  forces.evaluate(t, s, out);
  return out;
}

// Calls step(k, j, a, α) for each dynamic body, entry k of forces.bodies() and id j, with its
// accelerations at time t in state s: under constant forces the ForceModel's, with nothing stored
// per body, else evaluated into `out`.
template <typename Step>
void for_each_body(const ForceModel& forces, double t, const MotionState& s, Accelerations& out,
                   Step step) {
  if (forces.constant()) {
    forces.for_each_constant_acceleration(step);
    return;
  }
  evaluated(forces, t, s, out);
  const auto& ids = forces.bodies();
  for (std::size_t k = 0; k < ids.size(); ++k)
    step(k, ids[k], out.linear[ids[k]], out.angular[ids[k]]);
}

/// Semi-implicit (symplectic) Euler: v₁ = v₀ + a(x₀) h, x₁ = x₀ + v₁ h. First order.
class SymplecticEuler final : public Integrator {
 public:
  void advance(const ForceModel& forces, double t, double h, MotionState& s) override {
    const auto& rotates = forces.rotates();
    for_each_body(forces, t, s, a_, [&](std::size_t k, BodyId j, const Vec2& a, double alpha) {
      accelerate(s, j, rotates[k], a, alpha, h);
      move(s, j, rotates[k], s.velocity[j], s.angular_velocity[j], h);
    });
  }
  double impulse_position_share() const override { return 1.0; }
  PathShape path_under_constant_acceleration() const override { return PathShape::kEndVelocity; }

 private:
  Accelerations a_;
};

/// Velocity Verlet: x₁ = x₀ + (v₀ + a₀ h/2) h, v₁ = v₀ + (a₀ + a₁) h/2. Second order, symplectic,
/// exact when the acceleration is constant.
class VelocityVerlet final : public Integrator {
 public:
  void advance(const ForceModel& forces, double t, double h, MotionState& s) override {
    const auto& rotates = forces.rotates();
    // A body's move and its velocity's change by a₀ h depend on that body alone: one pass.
    const auto first_order = [&](std::size_t k, BodyId j, const Vec2& a, double alpha) {
      follow_parabola(s, j, rotates[k], a, alpha, h);
    };
    for_each_body(forces, t, s, a0_, first_order);
    if (forces.constant()) return;
    const auto& ids = forces.bodies();
    // Forces that depend on velocity see the velocity predicted at the end of the step. Sized
    // here: constant forces, the common case, never need the end's accelerations.
    evaluated(forces, t + h, s, a1_);
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const BodyId j = ids[k];
      accelerate(s, j, rotates[k], 0.5 * (a1_.linear[j] - a0_.linear[j]),
                 0.5 * (a1_.angular[j] - a0_.angular[j]), h);
    }
  }
  double impulse_position_share() const override { return 0.5; }
  PathShape path_under_constant_acceleration() const override { return PathShape::kParabola; }

 private:
  Accelerations a0_, a1_;
};

/// Classic fourth-order Runge–Kutta on (x, ϕ, v, ω).
class RungeKutta4 final : public Integrator {
 public:
  // Evaluates its first stage itself: the stages keep their accelerations together.
  void advance(const ForceModel& forces, double t, double h, MotionState& s) override {
    const auto& rotates = forces.rotates();
    if (forces.constant()) {
      // Every stage then has the same accelerations, and the stages' weighted slopes are exactly
      // v₀ + a h/2 for x and a for v: the four stages in one pass, without their rounding.
      forces.for_each_constant_acceleration(
          [&](std::size_t k, BodyId j, const Vec2& a, double alpha) {
            follow_parabola(s, j, rotates[k], a, alpha, h);
          });
      return;
    }
    const std::size_t n = s.position.size();
    stage_state_ = s;
    const auto& ids = forces.bodies();
    constexpr double c[4] = {0.0, 0.5, 0.5, 1.0};
    for (int i = 0; i < 4; ++i) {
      Stage& stage = stages_[i];
      stage.resize(n);
      if (i > 0) {
        const Stage& previous = stages_[i - 1];
        for (std::size_t q = 0; q < ids.size(); ++q) {
          const BodyId j = ids[q];
          stage_state_.position[j] = s.position[j] + c[i] * h * previous.velocity[j];
          stage_state_.velocity[j] = s.velocity[j] + c[i] * h * previous.acceleration.linear[j];
          if (rotates[q]) {
            // Stage angles stay unwrapped; only the final orientation is reduced to [0, 2π).
            stage_state_.angle[j] = s.angle[j] + c[i] * h * previous.angular_velocity[j];
            stage_state_.angular_velocity[j] =
                s.angular_velocity[j] + c[i] * h * previous.acceleration.angular[j];
          }
        }
      }
      forces.evaluate(t + c[i] * h, stage_state_, stage.acceleration);
      for (BodyId j : ids) {
        stage.velocity[j] = stage_state_.velocity[j];
        stage.angular_velocity[j] = stage_state_.angular_velocity[j];
      }
    }
    // The explicit return type evaluates Eigen's expression before the temporaries it refers to
    // go out of scope.
    const auto weighted = [this](auto member, BodyId j) -> decltype(member(stages_[0], j)) {
      return (member(stages_[0], j) + 2.0 * member(stages_[1], j) + 2.0 * member(stages_[2], j) +
              member(stages_[3], j)) /
             6.0;
    };
    for (std::size_t q = 0; q < ids.size(); ++q) {
      const BodyId j = ids[q];
      const Vec2 mean_v = weighted([](const Stage& st, BodyId b) { return st.velocity[b]; }, j);
      const double mean_w =
          weighted([](const Stage& st, BodyId b) { return st.angular_velocity[b]; }, j);
      const Vec2 mean_a =
          weighted([](const Stage& st, BodyId b) { return st.acceleration.linear[b]; }, j);
      const double mean_alpha =
          weighted([](const Stage& st, BodyId b) { return st.acceleration.angular[b]; }, j);
      move(s, j, rotates[q], mean_v, mean_w, h);
      accelerate(s, j, rotates[q], mean_a, mean_alpha, h);
    }
  }
  double impulse_position_share() const override { return 0.5; }
  PathShape path_under_constant_acceleration() const override { return PathShape::kParabola; }

 private:
  // The slopes of one stage: its velocities (the slope of x and ϕ) and accelerations.
  struct Stage {
    std::vector<Vec2> velocity;
    std::vector<double> angular_velocity;
    Accelerations acceleration;
    void resize(std::size_t n) {
      velocity.resize(n, Vec2::Zero());
      angular_velocity.resize(n);
      acceleration.resize(n);
    }
  };
  Stage stages_[4];
  MotionState stage_state_;
};

}  // namespace

std::unique_ptr<Integrator> make_integrator(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::SymplecticEuler:
      return std::make_unique<SymplecticEuler>();
    case IntegratorKind::RK4:
      return std::make_unique<RungeKutta4>();
    case IntegratorKind::VelocityVerlet:
      break;
  }
  return std::make_unique<VelocityVerlet>();
}

}  // namespace gp
