#pragma once
// What a peer engine (Chipmunk2D, Box2D) is given of a scene: the bodies exactly as our engine
// set them up — its mass, moment of inertia and centre of mass, its shapes re-expressed about the
// centre of mass — so that the peers differ from us in how they step, not in what they step.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/space.hpp"
#include "scene/scene.hpp"

namespace gp::peers {

/// A shape in its body's frame centred on the centre of mass, with its surface.
struct PeerShape {
  Shape shape;
  double restitution;  ///< C_R [1]
  double friction;     ///< μ [1]
};

/// A body as our engine holds it after Space::add_body.
struct PeerBody {
  std::string name;
  BodyType type;
  double mass;      ///< kg; infinite for static and kinematic bodies
  double moment;    ///< kg·m² about the centre of mass; infinite when the body cannot rotate
  BodyState start;  ///< centre of mass, orientation in [0, 2π), velocities at t = 0
  std::vector<PeerShape> shapes;
  Vec2 force = Vec2::Zero();  ///< N, constant, world axes
  double torque = 0.0;        ///< N·m, constant
  /// m, body frame, from the centre of mass to where `force` acts (it turns with the body); none:
  /// the force acts at the centre of mass.
  std::optional<Vec2> arm;
};

/// How a peer is set up.
enum class PeerConfig {
  /// As its users run it: its own rule for combining two surfaces, its own collision slop,
  /// restitution threshold and sleeping, its own iteration counts unless the scene sets ours.
  Default,
  /// Matched to our physics: our combining rule (C_R = max, μ = √(μ_a μ_b)), our slop and
  /// restitution threshold where the peer lets them be set, our iteration counts, sleeping off.
  Matched,
};

/// "default", "matched".
std::string_view config_name(PeerConfig config);
/// The configuration named `name`, or nothing.
std::optional<PeerConfig> config_from_name(std::string_view name);

/// The world of a scene as the peers are given it.
struct PeerScene {
  PeerConfig config;
  Vec2 gravity;                  ///< m/s², uniform
  std::optional<double> G;       ///< m³/(kg·s²): pairwise gravitation, applied by us as forces
  double restitution_threshold;  ///< m/s: slower impacts do not bounce
  double linear_slop;            ///< m: overlap left in resting contacts
  /// Sequential-impulse passes and position passes per step: ours under PeerConfig::Matched;
  /// under Default none when the scene keeps our defaults, so that each peer runs with its own.
  std::optional<int> velocity_iterations;
  std::optional<int> position_iterations;
  std::vector<PeerBody> bodies;
};

/// The bodies of `scene` as our engine sets them up (it builds a Space to ask it), for a peer
/// set up as `config` says. Throws InputError as build_space does.
PeerScene peer_scene(const Scene& scene, PeerConfig config = PeerConfig::Matched);

}  // namespace gp::peers
