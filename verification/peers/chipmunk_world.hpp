#pragma once
// A scene in Chipmunk2D 7 (Debian's libchipmunk, built with its debug checks on: cpAssertSoft and
// cpAssertSaneBody run on every step, which slows it down a little against a release build).
//
// Mapping: each body gets our engine's mass and moment (cpBodyNew(m, I); INFINITY for a body that
// cannot rotate) and its origin at our centre of mass, so Chipmunk's centre of gravity (0, 0) is
// ours; shapes carry no density, so Chipmunk never recomputes the mass from them. Circles,
// polygons (cpPolyShapeNewRaw: our vertices, already convex and counter-clockwise) and segments
// with their radius map exactly. Iterations: the scene's velocity_iterations when given (always
// under PeerConfig::Matched), else Chipmunk's default 10; Chipmunk has no position passes (it
// corrects overlap with a bias velocity: cpSpaceGetCollisionBias, by default 10% of the overlap
// left per 1/60 s). Chipmunk has no restitution threshold: every approach bounces with C_R, and
// its sleeping is off by default (an infinite sleep time threshold).
//
// PeerConfig::Default keeps Chipmunk's own rules: the two shapes' elasticities and frictions
// multiplied, collision slop 0.1 (a value for pixel units). PeerConfig::Matched installs a
// pre-solve callback, run on every step of every contact, that replaces them with our rule,
// C_R = max and μ = √(μ_a μ_b), and sets the collision slop to our linear_slop.

#include <chipmunk/chipmunk.h>

#include <vector>

#include "verification/peers/peer_world.hpp"

namespace gp::peers {

class ChipmunkWorld final : public PeerWorld {
 public:
  explicit ChipmunkWorld(const PeerScene& scene);
  ~ChipmunkWorld() override;

  BodyState state(BodyId body) const override;
  std::string describe() const override;

  /// Chipmunk's own body, to read back what it was given.
  const cpBody* body(BodyId id) const { return bodies_[id]; }

 protected:
  void advance(double dt) override;
  void apply(BodyId body, const Wrench& wrench) override;

 private:
  cpSpace* space_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
  PeerConfig config_;
};

}  // namespace gp::peers
