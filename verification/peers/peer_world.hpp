#pragma once
// A scene run by a peer engine (Chipmunk2D 7, Box2D 2.4, optionally Box2D 3) behind one interface,
// so that a run, a trajectory or a benchmark is written once for all and compared with our Space.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "verification/peers/applied_forces.hpp"
#include "verification/peers/peer_scene.hpp"

namespace gp::peers {

/// The peers this build has: Box2D 3 only when CMake was given a checkout of it (GP_BOX2D3_DIR,
/// which defines GP_HAVE_BOX2D3 for every target that links the peers).
enum class PeerEngine {
  Chipmunk,
  Box2d,
#ifdef GP_HAVE_BOX2D3
  Box2d3,
#endif
};

/// "chipmunk", "box2d", "box2d3".
std::string_view engine_name(PeerEngine engine);
/// The engine named `name`, or nothing.
std::optional<PeerEngine> engine_from_name(std::string_view name);
/// The peers' names for a message: "chipmunk or box2d", "chipmunk, box2d or box2d3".
std::string engine_choices();
/// The engine's precision and how its library was built, for beside its figures.
std::string_view library_build(PeerEngine engine);

class PeerWorld {
 public:
  explicit PeerWorld(const PeerScene& scene);
  virtual ~PeerWorld() = default;
  PeerWorld(const PeerWorld&) = delete;
  PeerWorld& operator=(const PeerWorld&) = delete;

  /// Advances by dt [s] > 0: hands every body its applied forces and torques (the peers clear
  /// them after each step), then steps the peer once.
  void step(double dt);

  std::size_t body_count() const { return names_.size(); }
  const std::string& name(BodyId body) const { return names_[body]; }
  /// The centre of mass, the orientation in [0, 2π) and the velocities, in double precision.
  virtual BodyState state(BodyId body) const = 0;
  /// The engine, its version and build, and the settings it runs with (iterations, slop).
  virtual std::string describe() const = 0;

 protected:
  /// Steps the peer by dt [s].
  virtual void advance(double dt) = 0;
  /// Sets the force [N] and torque [N·m] about the centre of mass of a dynamic body for the
  /// next step.
  virtual void apply(BodyId body, const Wrench& wrench) = 0;

 private:
  std::vector<std::string> names_;
  AppliedForces forces_;
  std::vector<BodyState> states_;  // read by the forces that depend on the state
};

/// The scene in `engine`. Throws InputError as build_space does.
std::unique_ptr<PeerWorld> make_peer(PeerEngine engine, const PeerScene& scene);

}  // namespace gp::peers
