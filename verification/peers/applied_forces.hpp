#pragma once
// The forces of a scene that the peers are handed anew before every step: Chipmunk2D and Box2D
// both clear a body's force and torque after each step, neither has pairwise gravitation, and
// neither turns a force's point of application with the body.

#include <vector>

#include "verification/peers/peer_scene.hpp"

namespace gp::peers {

/// A wrench on one dynamic body.
struct BodyWrench {
  BodyId body;
  Wrench wrench;  ///< N and N·m about the centre of mass
};

class AppliedForces {
 public:
  explicit AppliedForces(const PeerScene& scene);

  /// True when evaluate() reads the bodies' states: a force applied at a point (its torque turns
  /// with the body) or pairwise gravitation (TM:UniversalGravLaw, through GD:accelGravity).
  bool needs_states() const { return needs_states_; }

  /// The wrenches of the bodies that carry one, given every body's state (indexed by BodyId; read
  /// only when needs_states()). Pairwise gravitation is exerted, as in our engine, by dynamic
  /// bodies only and evaluated at the start of the step, where both peers' symplectic Euler
  /// evaluates forces.
  const std::vector<BodyWrench>& evaluate(const std::vector<BodyState>& states);

 private:
  struct Source {
    BodyId body;
    double mass;  // kg
    Vec2 force;   // N
    double torque;
    std::optional<Vec2> arm;
  };
  std::vector<Source> sources_;  // dynamic bodies with a force, or all of them under G
  std::optional<double> G_;
  std::vector<BodyId> attractors_;  // the dynamic bodies, when G is given
  std::vector<double> attractor_mass_;
  bool needs_states_ = false;
  std::vector<BodyWrench> wrenches_;
};

}  // namespace gp::peers
