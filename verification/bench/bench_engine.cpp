#include "verification/bench/bench_engine.hpp"

#include "engine/scene/scene_space.hpp"

#include <sstream>

namespace gp::bench {

std::string_view engine_label(Engine engine) {
  switch (engine) {
    case Engine::Ours:
      return "ours";
    case Engine::Chipmunk:
      return peers::engine_name(peers::PeerEngine::Chipmunk);
    case Engine::Box2d:
      break;
  }
  return peers::engine_name(peers::PeerEngine::Box2d);
}

EngineRun::EngineRun(Engine engine, const Scene& scene) {
  if (engine == Engine::Ours) {
    ours_ = build_space(scene);
  } else {
    peer_ = peers::make_peer(
        engine == Engine::Chipmunk ? peers::PeerEngine::Chipmunk : peers::PeerEngine::Box2d,
        peers::peer_scene(scene));
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
  text << "GamePhysics (double): " << integrator_name(s.integrator) << ", at most "
       << s.velocity_iterations << " velocity passes (ending below " << s.velocity_tolerance
       << " m/s) and " << s.position_iterations << " position passes, islands up to "
       << s.direct_solve_points << " points solved directly, linear slop " << s.linear_slop
       << " m, restitution threshold " << s.restitution_threshold << " m/s";
  return text.str();
}

std::vector<std::string> engine_settings(const Scene& scene) {
  std::vector<std::string> lines;
  for (Engine engine : kEngines) lines.push_back(EngineRun(engine, scene).describe());
  return lines;
}

}  // namespace gp::bench
