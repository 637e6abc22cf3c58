// Cross-validation with the engines people use (NFR:Correctness): every scene within the oracle's
// domain run by Chipmunk2D and Box2D at the same step as ours, each against the oracle. Both
// peers step with symplectic Euler, so the row judges ours with symplectic Euler against them,
// like for like (peers matched to our physics, ours running every pass as they do); ours with the
// scene's integrator stands beside, judged against the oracle in "accuracy against the oracle".
#include <algorithm>
#include <cmath>
#include <sstream>

#include "verification/bench/bench_engine.hpp"
#include "verification/suite/oracle_domain.hpp"
#include "verification/suite/peer_trajectory.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

namespace {

constexpr peers::PeerEngine kPeers[] = {peers::PeerEngine::Chipmunk, peers::PeerEngine::Box2d};

std::string describe(const Differences& d) {
  return "position " + figure(d.position) + " m, orientation " + figure(d.orientation) +
         " rad, velocity " + figure(d.velocity) + " m/s";
}

// Ours as the peers step: symplectic Euler, and every velocity pass run (the peers have no early
// stop); iterations, slop and restitution threshold are the scene's, which the matched peers take.
Scene like_the_peers(const Scene& scene) {
  Scene s = scene;
  s.settings.integrator = IntegratorKind::SymplecticEuler;
  s.settings.velocity_tolerance = 0.0;
  return s;
}

// Like for like, ours with symplectic Euler is judged to be of the peers' accuracy: its position
// error within this factor of the better peer's. The two peers differ from each other by up to
// 2.4× (pyramid6); ours is worse than the better peer on bouncing_ball (1.08 m against 0.58 m).
constexpr double kPeerFactor = 2.0;

// The peer's position error may come out below ours only by rounding: a relative 1e-12 of the
// largest position (at least 1 m) in the run.
double rounding(const Trajectory& oracle) {
  return 1e-12 * std::max(scales_of(oracle).position, 1.0);
}

}  // namespace

std::vector<Check> peer_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                               OracleReferences& references, CsvFiles& data) {
  CheckList list("peers against the oracle");
  if (!scenes.empty()) {
    // The settings every row below runs with, on the first scene (a scene's own iterations,
    // slop and threshold replace ours, and the matched peers take them too).
    const Scene& first = scenes.front().scene;
    std::string engines =
        "ours, default: " + bench::EngineRun(bench::Engine::Ours, first).describe() +
        "; ours, like the peers: " +
        bench::EngineRun(bench::Engine::Ours, like_the_peers(first)).describe();
    for (const auto engine : {bench::Engine::ChipmunkMatched, bench::Engine::Box2dMatched}) {
      engines += "; " + std::string(bench::engine_label(engine)) + ": " +
                 bench::EngineRun(engine, first).describe();
    }
    list.report("engines and settings", "NFR:Correctness", engines);
  }
  std::ostringstream csv;
  csv << "scene,engine,dt,position,orientation,velocity\n";
  for (const auto& [name, original] : scenes) {
    Scene scene = original;
    if (o.quick) scene.duration = std::min(scene.duration, 1.0);
    if (o.progress) *o.progress << "  peers: " << name << "\n";
    const std::vector<double> times = output_instants(scene.duration, scene.dt);
    const auto reference = references.find(list, name, scene, times, reference_options(scene));
    if (!reference) continue;
    const Trajectory& oracle = reference->trajectory;
    const IntegratorKind own = scene.settings.integrator;
    const Differences ours = compare(run_engine(scene, own, scene.dt), oracle);
    const Scene alike = like_the_peers(scene);
    const Differences ours_se =
        compare(run_engine(alike, alike.settings.integrator, scene.dt), oracle);
    std::string measured = "ours (" + std::string(integrator_name(own)) +
                           ", double): " + describe(ours) +
                           "; ours (symplectic_euler, double, all passes): " + describe(ours_se);
    double best_peer = INFINITY;
    for (const auto engine : kPeers) {
      Differences d;
      try {
        d = compare(run_peer_trajectory(engine, scene), oracle);
      } catch (const std::exception& e) {
        cannot_run(list, name, std::string(peers::engine_name(engine)), e.what());
        continue;
      }
      measured += "; " + std::string(peers::engine_name(engine)) + " matched (symplectic Euler, " +
                  (engine == peers::PeerEngine::Box2d ? "float" : "double") + "): " + describe(d);
      best_peer = std::min(best_peer, d.position);
      csv << name << "," << peers::engine_name(engine) << "," << scene.dt << "," << d.position
          << "," << d.orientation << "," << d.velocity << "\n";
    }
    for (const auto& [label, d] : {std::pair{std::string("ours"), ours},
                                   std::pair{std::string("ours_symplectic_euler"), ours_se}}) {
      csv << name << "," << label << "," << scene.dt << "," << d.position << "," << d.orientation
          << "," << d.velocity << "\n";
    }
    const double floor = rounding(oracle);
    list.within(name + ", dt = " + figure(scene.dt) + " s", "NFR:Correctness", measured,
                "ours with symplectic Euler within " + figure(kPeerFactor) +
                    "× the better matched peer's position error, or rounding (" + figure(floor) +
                    " m)",
                {{ours_se.position, std::max(kPeerFactor * best_peer, floor)}},
                "a comparison: the limit is the better peer's error, not a tolerance");
  }
  data.emplace_back("peers.csv", csv.str());
  return list.rows();
}

}  // namespace gp::verification
