#include "verification/peers/peer_world.hpp"

#include "verification/peers/box2d_world.hpp"
#include "verification/peers/chipmunk_world.hpp"

namespace gp::peers {

std::string_view engine_name(PeerEngine engine) {
  return engine == PeerEngine::Chipmunk ? "chipmunk" : "box2d";
}

std::optional<PeerEngine> engine_from_name(std::string_view name) {
  for (PeerEngine engine : {PeerEngine::Chipmunk, PeerEngine::Box2d}) {
    if (engine_name(engine) == name) return engine;
  }
  return std::nullopt;
}

PeerWorld::PeerWorld(const PeerScene& scene) : forces_(scene) {
  for (const PeerBody& body : scene.bodies) names_.push_back(body.name);
}

void PeerWorld::step(double dt) {
  if (forces_.needs_states()) {
    states_.resize(body_count());
    for (BodyId id = 0; id < body_count(); ++id) states_[id] = state(id);
  }
  for (const BodyWrench& w : forces_.evaluate(states_)) apply(w.body, w.wrench);
  advance(dt);
}

std::unique_ptr<PeerWorld> make_peer(PeerEngine engine, const PeerScene& scene) {
  if (engine == PeerEngine::Chipmunk) return std::make_unique<ChipmunkWorld>(scene);
  return std::make_unique<Box2dWorld>(scene);
}

}  // namespace gp::peers
