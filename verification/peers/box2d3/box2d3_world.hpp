#pragma once
// A scene in Box2D 3.x, built from the checkout given to CMake as GP_BOX2D3_DIR (only then: the
// build defines GP_HAVE_BOX2D3). Box2D 3 has the include path and the type names (b2Vec2, ...) of
// the Box2D 2.4 that Box2dWorld links, so this header shows only our types and Box2D 3's headers
// are included by box2d3_world.cpp alone. Written against the C API of Box2D 3.2 (commit 617d32ab).
//
// Mapping, as Box2dWorld's: each body's origin is our centre of mass and b2Body_SetMassData gives
// our mass and moment (centre (0, 0)); shapes have density 0 and never update the mass. A body
// that cannot rotate has its rotation locked. Circles map exactly, and so do polygons: Box2D 3's
// polygons are made with radius 0 (no skin), from b2ComputeHull, which welds vertices closer than
// 4 linear slops (0.02 m). A segment of radius r > 0 is a b2Capsule, of radius 0 a two-sided
// b2Segment (segments do not collide with segments). Box2D 3's own combining rules are ours
// (μ = √(μ_a μ_b), C_R = max). Its solver is its own in either configuration: soft contacts
// (30 Hz, damping ratio 10, pushed apart at most 3 m/s), kSubSteps sub-steps of symplectic Euler
// with a relaxing pass, speculative contacts, continuous collision of dynamic against static
// bodies; the scene's iteration counts do not map onto it and are not used.
//
// PeerConfig::Default: b2DefaultWorldDef (restitution threshold 1 m/s, sleeping on).
// PeerConfig::Matched: our restitution threshold, sleeping off (as Box2D 3's benchmarks run).

#include <memory>
#include <string_view>
#include <vector>

#include "verification/peers/peer_world.hpp"

namespace gp::peers {

/// What Box2D 3 holds of a body, read back through its own API.
struct Box2d3Body {
  double mass;        ///< kg; 0 for static and kinematic bodies
  double moment;      ///< kg·m² about the centre of mass
  Vec2 local_center;  ///< m, body frame: (0, 0), as the origin is our centre of mass
  Vec2 origin;        ///< m, world
  std::vector<Vec2> polygon_vertices;  ///< m, world: the vertices of its polygons
  double polygon_radius;               ///< m: the largest rounding of its polygons
};

class Box2d3World final : public PeerWorld {
 public:
  /// Box2D 3's recommended sub-steps (b2World_Step takes them on every call).
  static constexpr int kSubSteps = 4;

  explicit Box2d3World(const PeerScene& scene);
  ~Box2d3World() override;

  BodyState state(BodyId body) const override;
  std::string describe() const override;

  /// Box2D 3's own record of a body, to read back what it was given.
  Box2d3Body body(BodyId id) const;

  /// Its precision and how its library was built ("float, Box2D 3.2.0 built from GP_BOX2D3_DIR,
  /// SSE2, asserts off, 4 sub-steps").
  static std::string_view build();

 protected:
  void advance(double dt) override;
  void apply(BodyId body, const Wrench& wrench) override;

 private:
  struct Box2d;  // Box2D 3's world and bodies, defined where its headers are seen
  std::unique_ptr<Box2d> box2d_;
  PeerConfig config_;
};

}  // namespace gp::peers
