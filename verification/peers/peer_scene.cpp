#include "verification/peers/peer_scene.hpp"

#include "engine/scene/scene_space.hpp"
#include "engine/setup/mass_setup.hpp"
#include "engine/space_impl.hpp"

namespace gp::peers {

PeerScene peer_scene(const Scene& scene) {
  const std::unique_ptr<Space> space = build_space(scene);
  const Settings defaults;
  const Settings& s = scene.settings;
  PeerScene peer{s.gravity,    s.G, s.restitution_threshold, s.linear_slop, std::nullopt,
                 std::nullopt, {}};
  if (s.velocity_iterations != defaults.velocity_iterations) {
    peer.velocity_iterations = s.velocity_iterations;
  }
  if (s.position_iterations != defaults.position_iterations) {
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
