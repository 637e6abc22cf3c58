// Cross-validation with the engines people use (NFR:Correctness): every scene within the oracle's
// domain run by Chipmunk2D and Box2D at the same step as ours, each against the oracle.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "verification/suite/oracle_domain.hpp"
#include "verification/suite/peer_trajectory.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

namespace {

std::string describe(const Differences& d) {
  return "position " + figure(d.position) + " m, orientation " + figure(d.orientation) +
         " rad, velocity " + figure(d.velocity) + " m/s";
}

}  // namespace

std::vector<Check> peer_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                               CsvFiles& data) {
  CheckList list("peers against the oracle");
  std::ostringstream csv;
  csv << "scene,engine,dt,position,orientation,velocity\n";
  for (const auto& [name, original] : scenes) {
    Scene scene = original;
    if (o.quick) scene.duration = std::min(scene.duration, 1.0);
    const std::vector<double> times = output_instants(scene.duration, scene.dt);
    const auto reference = oracle_reference(list, name, scene, times, reference_options(scene));
    if (!reference) continue;
    const Trajectory& oracle = reference->trajectory;
    if (o.progress) *o.progress << "  peers: " << name << "\n";
    const Differences ours =
        compare(run_engine(scene, scene.settings.integrator, scene.dt), oracle);
    std::string measured =
        "ours (" + std::string(integrator_name(scene.settings.integrator)) + "): " + describe(ours);
    double best_peer = INFINITY;
    for (const auto engine : {peers::PeerEngine::Chipmunk, peers::PeerEngine::Box2d}) {
      Differences d;
      try {
        d = compare(run_peer_trajectory(engine, scene), oracle);
      } catch (const std::exception& e) {
        cannot_run(list, name, std::string(peers::engine_name(engine)), e.what());
        continue;
      }
      measured += "; " + std::string(peers::engine_name(engine)) + ": " + describe(d);
      best_peer = std::min(best_peer, d.position);
      csv << name << "," << peers::engine_name(engine) << "," << scene.dt << "," << d.position
          << "," << d.orientation << "," << d.velocity << "\n";
    }
    csv << name << ",ours," << scene.dt << "," << ours.position << "," << ours.orientation << ","
        << ours.velocity << "\n";
    list.check(name + ", dt = " + figure(scene.dt) + " s", "NFR:Correctness", measured,
               "ours at least as accurate as the better peer (position), to rounding (1e-12 m)",
               ours.position <= std::max(best_peer, 1e-12));
  }
  data.emplace_back("peers.csv", csv.str());
  return list.rows();
}

}  // namespace gp::verification
