#pragma once
// A scene in Box2D 2.4 (Debian's libbox2d): single precision, so positions carry a relative
// rounding of about 1e-7 and trajectories agree with ours to about 1e-4 relative at best.
//
// Mapping: each body's origin is our centre of mass and b2MassData gives our mass and moment
// (centre (0, 0)); fixtures have density 0, so Box2D never recomputes the mass. A body that
// cannot rotate is fixedRotation. Circles map exactly. Box2D rounds polygons and edges by a skin
// of b2_polygonRadius (0.01 m): polygons are inset by it, so that the rounded outline is ours with
// corners rounded by 0.01 m; a segment of radius r > 0.01 m is its exact capsule as three
// fixtures (a box of half-thickness r − 0.01 m plus two discs of radius r at the ends); a
// segment of radius r ≤ 0.01 m is a b2EdgeShape, whose skin makes it 0.01 − r m too thick; edges
// do not collide with edges. Box2D's combination rule is ours (C_R = max, μ = √(μ_a μ_b)). Box2D
// keeps its compile-time linear slop (0.005 m) and continuous collision (dynamic against static
// only) in either configuration.
//
// PeerConfig::Default: Box2D's per-fixture restitution threshold (1 m/s), sleeping on (its
// default), its recommended 8 velocity and 3 position iterations unless the scene sets its own.
// PeerConfig::Matched: our restitution threshold, sleeping off (our engine never sleeps), our
// iteration counts.

#include <box2d/box2d.h>

#include <memory>
#include <vector>

#include "verification/peers/peer_world.hpp"

namespace gp::peers {

class Box2dWorld final : public PeerWorld {
 public:
  /// Box2D's recommended iterations (b2World::Step takes them on every call).
  static constexpr int kDefaultVelocityIterations = 8;
  static constexpr int kDefaultPositionIterations = 3;

  explicit Box2dWorld(const PeerScene& scene);

  BodyState state(BodyId body) const override;
  std::string describe() const override;

  /// Box2D's own body, to read back what it was given.
  const b2Body* body(BodyId id) const { return bodies_[id]; }

 protected:
  void advance(double dt) override;
  void apply(BodyId body, const Wrench& wrench) override;

 private:
  std::unique_ptr<b2World> world_;  // owns the bodies and fixtures
  std::vector<b2Body*> bodies_;
  int velocity_iterations_;
  int position_iterations_;
  float restitution_threshold_;
  PeerConfig config_;
};

}  // namespace gp::peers
