#pragma once
// Our engine and the peers behind one stepping interface, so that one benchmark body times them
// all alike.

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "engine/space.hpp"
#include "scene/scene.hpp"
#include "verification/peers/peer_world.hpp"

namespace gp::bench {

/// Ours, and each peer twice: as its users run it (peers::PeerConfig::Default) and matched to our
/// physics (peers::PeerConfig::Matched); Box2D 3 only in a build that has it (peers::PeerEngine).
enum class Engine {
  Ours,
  ChipmunkDefault,
  ChipmunkMatched,
  Box2dDefault,
  Box2dMatched,
#ifdef GP_HAVE_BOX2D3
  Box2d3Default,
  Box2d3Matched,
#endif
};

/// Ours first, as the ratios are of our time to a peer's: the order of the runs and of the tables.
inline constexpr std::array kEngines{
    Engine::Ours,          Engine::ChipmunkDefault, Engine::ChipmunkMatched,
    Engine::Box2dDefault,  Engine::Box2dMatched,
#ifdef GP_HAVE_BOX2D3
    Engine::Box2d3Default, Engine::Box2d3Matched,
#endif
};

/// Ours on two threads, run by gamephysics_bench beside the engines (ours and the peers on one):
/// its row's ours/engine is the speed-up the second thread gives.
inline constexpr std::string_view kOursTwoThreads = "ours-2-threads";

/// Ours with each integrator other than the default, run by gamephysics_bench beside the engines
/// (on one thread): its row's ours/engine is the default's time over its own, so that an
/// integrator that falls onto a slow path shows (below 1: slower than the default).
struct OursIntegrator {
  std::string_view label;
  IntegratorKind integrator;
};
inline constexpr std::array<OursIntegrator, 2> kOursIntegrators{
    OursIntegrator{"ours-symplectic-euler", IntegratorKind::SymplecticEuler},
    OursIntegrator{"ours-rk4", IntegratorKind::RK4}};

/// "ours", "chipmunk-default", "chipmunk-matched", "box2d-default", "box2d-matched",
/// "box2d3-default", "box2d3-matched".
std::string_view engine_label(Engine engine);

/// The engine's precision and how its library was built, for beside every speed figure: ours in
/// double from this build; the peers as peers::library_build says (Chipmunk2D in double and
/// Box2D 2.4 in float, both Debian's builds with their debug checks on; Box2D 3 in float, built
/// from GP_BOX2D3_DIR).
std::string_view engine_build(Engine engine);
/// The same for the engine labelled `label` (engine_label); empty for an unknown label.
std::string_view engine_build(std::string_view label);

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
