// Every scene against the oracle with every game integrator, and the two oracles against each
// other.
#include <algorithm>
#include <sstream>

#include "engine/output/output_times.hpp"
#include "verification/suite/oracle_trajectory.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

namespace {

constexpr IntegratorKind kIntegrators[] = {IntegratorKind::SymplecticEuler,
                                           IntegratorKind::VelocityVerlet, IntegratorKind::RK4};

// Constant accelerations make velocity Verlet and RK4 exact between impacts, and impacts are
// resolved at their exact time: these runs must match the oracle to rounding.
bool exact_expected(const Scene& scene, IntegratorKind kind) {
  if (kind == IntegratorKind::SymplecticEuler || scene.settings.G) return false;
  return std::none_of(scene.bodies.begin(), scene.bodies.end(),
                      [](const BodyDef& b) { return b.force_point.has_value(); });
}

std::string ids_of(const Trajectory& reference) {
  return reference.impacts.empty() ? "IM:transMot IM:rotMot"
                                   : "IM:transMot IM:rotMot IM:col2D GD:impulse";
}

}  // namespace

std::vector<Check> accuracy_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                                   CsvFiles& data) {
  CheckList list("accuracy against the oracle");
  std::ostringstream csv;
  csv << "scene,integrator,dt,position,orientation,velocity,angular_velocity,end_position,"
         "collision_time,unmatched_impacts\n";
  for (const auto& [name, original] : scenes) {
    Scene scene = original;
    if (o.quick) scene.duration = std::min(scene.duration, 1.0);
    if (o.progress) *o.progress << "  accuracy: " << name << "\n";
    const OutputTimes instants(scene.duration, scene.dt);
    std::vector<double> times;
    for (std::size_t k = 0; k < instants.size(); ++k) times.push_back(instants[k]);
    OracleOptions options;
    // Orbits accumulate the per-step tolerance over many steps: tighter there, so that the two
    // oracles agree to 1e-9.
    options.rtol = options.atol = scene.settings.G ? 1e-14 : 1e-12;
    Trajectory cvode, arkode;
    try {
      cvode = run_oracle_trajectory(scene, times, options);
      options.method = OracleMethod::ArkodeErk;
      arkode = run_oracle_trajectory(scene, times, options);
    } catch (const OracleDomainError& e) {
      list.report(name, "", std::string("outside the oracle's domain: ") + e.what());
      continue;
    }
    const Differences agree = compare(arkode, cvode);
    const Scales scale = scales_of(cvode);
    const double position = agree.position / std::max(scale.position, 1.0);
    const double velocity = agree.velocity / std::max(scale.velocity, 1.0);
    list.check(name + ": ARKODE against CVODE", "NFR:Correctness",
               "position " + figure(position) + ", velocity " + figure(velocity) +
                   " (relative to the largest |p|, |v|, at least 1), t_c " +
                   figure(agree.collision_time) + " s",
               "all ≤ 1e-9",
               position <= 1e-9 && velocity <= 1e-9 && agree.collision_time <= 1e-9 &&
                   agree.unmatched_impacts == 0);
    for (IntegratorKind kind : kIntegrators) {
      const Differences d = compare(run_engine(scene, kind, scene.dt), cvode);
      const std::string label =
          name + ", " + std::string(integrator_name(kind)) + ", dt = " + figure(scene.dt) + " s";
      const std::string measured =
          "position " + figure(d.position) + " m, orientation " + figure(d.orientation) +
          " rad, velocity " + figure(d.velocity) + " m/s, at end " + figure(d.end_position) +
          " m, t_c " + figure(d.collision_time) + " s" +
          (d.unmatched_impacts ? ", " + std::to_string(d.unmatched_impacts) + " unmatched impacts"
                               : "");
      if (exact_expected(scene, kind)) {
        list.check(label, ids_of(cvode), measured, "position, velocity and t_c ≤ 1e-9",
                   d.position <= 1e-9 && d.velocity <= 1e-9 && d.collision_time <= 1e-9 &&
                       d.unmatched_impacts == 0);
      } else {
        list.report(label, ids_of(cvode), measured);
      }
      csv << name << "," << integrator_name(kind) << "," << scene.dt << "," << d.position << ","
          << d.orientation << "," << d.velocity << "," << d.angular_velocity << ","
          << d.end_position << "," << d.collision_time << "," << d.unmatched_impacts << "\n";
    }
  }
  data.emplace_back("accuracy.csv", csv.str());
  return list.rows();
}

}  // namespace gp::verification
