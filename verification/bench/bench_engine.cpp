#include "verification/bench/bench_engine.hpp"

#include "engine/scene/scene_space.hpp"
#include "verification/bench/formatted.hpp"

#include <sstream>

namespace gp::bench {

namespace {

struct PeerOf {
  Engine engine;
  std::string_view label;
  peers::PeerEngine peer;
  peers::PeerConfig config;
};

constexpr PeerOf kPeers[] = {
    {Engine::ChipmunkDefault, "chipmunk-default", peers::PeerEngine::Chipmunk,
     peers::PeerConfig::Default},
    {Engine::ChipmunkMatched, "chipmunk-matched", peers::PeerEngine::Chipmunk,
     peers::PeerConfig::Matched},
    {Engine::Box2dDefault, "box2d-default", peers::PeerEngine::Box2d, peers::PeerConfig::Default},
    {Engine::Box2dMatched, "box2d-matched", peers::PeerEngine::Box2d, peers::PeerConfig::Matched},
#ifdef GP_HAVE_BOX2D3
    {Engine::Box2d3Default, "box2d3-default", peers::PeerEngine::Box2d3,
     peers::PeerConfig::Default},
    {Engine::Box2d3Matched, "box2d3-matched", peers::PeerEngine::Box2d3,
     peers::PeerConfig::Matched},
#endif
};

const PeerOf* peer_of(Engine engine) {
  for (const PeerOf& p : kPeers) {
    if (p.engine == engine) return &p;
  }
  return nullptr;
}

}  // namespace

std::string_view engine_label(Engine engine) {
  const PeerOf* p = peer_of(engine);
  return p ? p->label : "ours";
}

std::string_view engine_build(Engine engine) {
  const PeerOf* p = peer_of(engine);
  return p ? peers::library_build(p->peer) : "double, this build";
}

std::string_view engine_build(std::string_view label) {
  if (label == kOursTwoThreads) return engine_build(Engine::Ours);
  for (const OursIntegrator& variant : kOursIntegrators) {
    if (label == variant.label) return engine_build(Engine::Ours);
  }
  for (Engine engine : kEngines) {
    if (engine_label(engine) == label) return engine_build(engine);
  }
  return "";
}

EngineRun::EngineRun(Engine engine, const Scene& scene) {
  if (const PeerOf* p = peer_of(engine)) {
    peer_ = peers::make_peer(p->peer, peers::peer_scene(scene, p->config));
  } else {
    ours_ = build_space(scene);
  }
}

void EngineRun::step(double dt) {
  if (ours_) {
    ours_->step(dt);
  } else {
    peer_->step(dt);
  }
}

BodyState EngineRun::state(BodyId body) const {
  return ours_ ? ours_->state(body) : peer_->state(body);
}

std::string EngineRun::describe() const {
  if (peer_) return peer_->describe();
  const Settings& s = ours_->settings();
  std::ostringstream text;
  text << "GamePhysics (double, " << integrator_name(s.integrator) << "): at most "
       << s.velocity_iterations << " velocity passes ("
       << (s.velocity_tolerance > 0.0 ? "ending once one changes no velocity by more than " +
                                            formatted("%g", s.velocity_tolerance) + " m/s"
                                      : std::string("all run unless one changes nothing"))
       << ") and " << s.position_iterations << " position passes, islands up to "
       << s.direct_solve_points << " points solved directly (" << s.direct_solve_uneven_points
       << " where masses differ more than " << s.direct_solve_mass_ratio << "-fold, "
       << s.direct_solve_resting_points
       << " at rest where the carried impulses do not hold), linear slop " << s.linear_slop
       << " m, restitution threshold " << s.restitution_threshold << " m/s, no sleeping";
  return text.str();
}

std::vector<std::string> engine_settings(const Scene& scene) {
  std::vector<std::string> lines;
  for (Engine engine : kEngines) {
    lines.push_back(std::string(engine_label(engine)) + ": " + EngineRun(engine, scene).describe());
  }
  return lines;
}

}  // namespace gp::bench
