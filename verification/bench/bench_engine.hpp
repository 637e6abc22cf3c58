#pragma once
// Our engine and the two peers behind one stepping interface, so that one benchmark body times
// all three alike.

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "engine/space.hpp"
#include "scene/scene.hpp"
#include "verification/peers/peer_world.hpp"

namespace gp::bench {

enum class Engine { Ours, Chipmunk, Box2d };

/// Ours first, as the ratios are of our time to a peer's: the order of the runs and of the tables.
inline constexpr std::array<Engine, 3> kEngines{Engine::Ours, Engine::Chipmunk, Engine::Box2d};

/// "ours", "chipmunk", "box2d".
std::string_view engine_label(Engine engine);

/// A scene set up in one engine, ready to step from t = 0.
class EngineRun {
 public:
  EngineRun(Engine engine, const Scene& scene);

  void step(double dt);
  BodyState state(BodyId body) const;
  /// The engine and the settings it runs with.
  std::string describe() const;

 private:
  std::unique_ptr<Space> ours_;
  std::unique_ptr<peers::PeerWorld> peer_;
};

/// The engines and the settings they run `scene` with, a line each in the order of kEngines.
std::vector<std::string> engine_settings(const Scene& scene);

}  // namespace gp::bench
