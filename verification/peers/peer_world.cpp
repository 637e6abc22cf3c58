#include "verification/peers/peer_world.hpp"

#include <algorithm>
#include <iterator>

#include "verification/peers/box2d3/box2d3_world.hpp"
#include "verification/peers/box2d_world.hpp"
#include "verification/peers/chipmunk_world.hpp"

namespace gp::peers {

namespace {

template <class World>
std::unique_ptr<PeerWorld> make(const PeerScene& scene) {
  return std::make_unique<World>(scene);
}

struct Peer {
  PeerEngine engine;
  std::string_view name;
  std::unique_ptr<PeerWorld> (*make)(const PeerScene&);
  std::string_view (*build)();
};

// The one list of the peers compiled in. Debian's libchipmunk.so.7.0.3 holds the banner
// "Chipmunk v%s (Debug Enabled)" and the messages of cpBodySanityCheck, and calls cpMessage from
// 168 places; libbox2d.so.2.4.1 calls __assert_fail from 195: neither was built with NDEBUG.
constexpr Peer kPeers[] = {
    {PeerEngine::Chipmunk, "chipmunk", make<ChipmunkWorld>,
     [] { return std::string_view("double, Debian build, debug checks on"); }},
    {PeerEngine::Box2d, "box2d", make<Box2dWorld>,
     [] { return std::string_view("float, Debian build, asserts on"); }},
#ifdef GP_HAVE_BOX2D3
    {PeerEngine::Box2d3, "box2d3", make<Box2d3World>, Box2d3World::build},
#endif
};

const Peer& peer(PeerEngine engine) {
  return *std::find_if(std::begin(kPeers), std::end(kPeers),
                       [engine](const Peer& p) { return p.engine == engine; });
}

}  // namespace

std::string_view engine_name(PeerEngine engine) {
  return peer(engine).name;
}

std::optional<PeerEngine> engine_from_name(std::string_view name) {
  for (const Peer& p : kPeers) {
    if (p.name == name) return p.engine;
  }
  return std::nullopt;
}

std::string engine_choices() {
  std::string text;
  for (std::size_t i = 0; i < std::size(kPeers); ++i) {
    if (i > 0) text += i + 1 < std::size(kPeers) ? ", " : " or ";
    text += kPeers[i].name;
  }
  return text;
}

std::string_view library_build(PeerEngine engine) {
  return peer(engine).build();
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
  return peer(engine).make(scene);
}

}  // namespace gp::peers
