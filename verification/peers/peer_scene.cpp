#include "verification/peers/peer_scene.hpp"

#include "engine/scene/scene_space.hpp"
#include "engine/setup/mass_setup.hpp"
#include "engine/space_impl.hpp"

namespace gp::peers {

std::string_view config_name(PeerConfig config) {
  return config == PeerConfig::Default ? "default" : "matched";
}

std::optional<PeerConfig> config_from_name(std::string_view name) {
  for (PeerConfig config : {PeerConfig::Default, PeerConfig::Matched}) {
    if (config_name(config) == name) return config;
  }
  return std::nullopt;
}

PeerScene peer_scene(const Scene& scene, PeerConfig config) {
  const std::unique_ptr<Space> space = build_space(scene);
  const Settings defaults;
  const Settings& s = scene.settings;
  PeerScene peer{config,        s.gravity,    s.G,          s.restitution_threshold,
                 s.linear_slop, std::nullopt, std::nullopt, {}};
  const bool matched = config == PeerConfig::Matched;
  if (matched || s.velocity_iterations != defaults.velocity_iterations) {
    peer.velocity_iterations = s.velocity_iterations;
  }
  if (matched || s.position_iterations != defaults.position_iterations) {
    peer.position_iterations = s.position_iterations;
  }
  for (BodyId id = 0; id < space->body_count(); ++id) {
    const BodyDef& def = scene.bodies[id];
    PeerBody body{def.name,     def.type, space->mass(id), space->moment(id), space->state(id), {},
                  Vec2::Zero(), 0.0,      std::nullopt};
    if (def.type == BodyType::Dynamic) {
      body.force = def.force;
      body.torque = def.torque;
      // The Space keeps the arm private; mass_setup is where it takes the centre from.
      if (def.force_point) body.arm = *def.force_point - mass_setup(def).local_center;
    }
    peer.bodies.push_back(std::move(body));
  }
  const BodyShapes& shapes = SpaceInternals::context(*space).shapes;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const ShapeRecord& r = shapes[i];
    peer.bodies[r.body].shapes.push_back({Shape::copy_of(r.local), r.restitution, r.friction});
  }
  return peer;
}

}  // namespace gp::peers
