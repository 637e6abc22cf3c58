// Speed against error: CPU time per simulated second against the largest position error versus
// the oracle, for every game integrator and for Chipmunk2D and Box2D at six step sizes, and for
// CVODE at six tolerances.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "verification/suite/oracle_domain.hpp"
#include "verification/suite/oracle_trajectory.hpp"
#include "verification/suite/peer_trajectory.hpp"
#include "verification/suite/scene_builders.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

namespace {

// Common instants for every step size below: multiples of the coarsest step.
constexpr double kCoarsest = 1.0 / 15;

}  // namespace

std::vector<Check> work_precision_checks(const std::vector<NamedScene>& scenes,
                                         const SuiteOptions& o, CsvFiles& data) {
  CheckList list("speed against error");
  std::ostringstream csv;
  csv << "scene,method,parameter,cpu_seconds_per_simulated_second,position_error\n";
  std::vector<NamedScene> chosen;
  for (const char* name :
       {"projectile", "bouncing_ball", "spinning_box", "orbit", "oblique", "ramp_slide",
        "disc_roll", "box_drop", "stack3", "pyramid6", "heavy_stack"}) {
    for (const auto& s : scenes) {
      if (s.name == name) chosen.push_back(s);
    }
  }
  chosen.push_back({"rain100", rain100()});
  for (auto& [name, scene] : chosen) {
    if (o.quick) scene.duration = std::min(scene.duration, 0.5);
    if (o.progress) *o.progress << "  speed against error: " << name << "\n";
    const std::vector<double> instants = output_instants(scene.duration, kCoarsest);
    const auto solved = oracle_reference(list, name, scene, instants, reference_options(scene));
    if (!solved) continue;
    const Trajectory& reference = solved->trajectory;
    const double simulated = std::max(scene.duration, 1e-9);
    std::size_t points = 0;
    std::string skipped;
    for (IntegratorKind kind :
         {IntegratorKind::SymplecticEuler, IntegratorKind::VelocityVerlet, IntegratorKind::RK4}) {
      for (int k = 0; k < (o.quick ? 2 : 6); ++k) {
        const double dt = kCoarsest / (1 << k);
        Scene stepped = scene;
        stepped.output_dt = kCoarsest;
        stepped.dt = dt;
        const Trajectory run = run_engine(stepped, kind, dt);
        const Differences d = compare(sample_at(run, instants), reference);
        csv << name << "," << integrator_name(kind) << "," << dt << ","
            << time_engine(stepped, kind, dt) / simulated << "," << d.position << "\n";
        ++points;
      }
    }
    // The peers at the same step sizes, matched to our physics (our iterations, slop and
    // combining rule): their symplectic Euler beside ours on the same diagram.
    for (const auto engine : {peers::PeerEngine::Chipmunk, peers::PeerEngine::Box2d}) {
      for (int k = 0; k < (o.quick ? 2 : 6); ++k) {
        Scene stepped = scene;
        stepped.dt = kCoarsest / (1 << k);
        const Differences d =
            compare(sample_at(run_peer_trajectory(engine, stepped), instants), reference);
        csv << name << "," << peers::engine_name(engine) << "," << stepped.dt << ","
            << time_peer(engine, stepped) / simulated << "," << d.position << "\n";
        ++points;
      }
    }
    for (int k = 0; k < (o.quick ? 2 : 6); ++k) {
      OracleOptions options;
      options.rtol = options.atol = std::pow(10.0, -4 - k);
      Trajectory run;
      try {
        run = run_oracle_trajectory(scene, instants, options);
      } catch (const OracleDomainError& e) {
        // Loose tolerances can miss an event: a point the diagram cannot have, said in its row.
        skipped += " cvode-adams at rtol " + figure(options.rtol) + ": " + e.what() + ";";
        continue;
      }
      const Differences d = compare(run, reference);
      csv << name << ",cvode-adams," << options.rtol << "," << run.cpu_seconds / simulated << ","
          << d.position << "\n";
      ++points;
    }
    list.report(name, "LC:Variable-ODE-Solver NFR:Performance",
                std::to_string(points) + " points: work-precision diagram wp_" + name +
                    ".png; ours (double) with each integrator, Chipmunk2D (double) and Box2D "
                    "(float) matched, both symplectic Euler" +
                    (skipped.empty() ? "" : "; not drawn:" + skipped));
  }
  data.emplace_back("work_precision.csv", csv.str());
  return list.rows();
}

}  // namespace gp::verification
