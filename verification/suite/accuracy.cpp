// Every scene against the oracle with every game integrator, and the two oracles against each
// other.
#include <algorithm>
#include <span>
#include <sstream>
#include <string_view>

#include "verification/suite/oracle_domain.hpp"
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

// The contact scenes: the engine resolves contact by sequential impulses with a penetration slop
// and position correction, not exactly, so its error is bounded by what was measured in the full
// run (at most ×10; velocities near rounding ×4): the largest position [m] and velocity [m/s]
// error against the oracle at the scene's dt, first order (symplectic Euler) and the others.
struct Bound {
  double position;
  double velocity;
};
struct ContactBound {
  std::string_view scene;
  Bound first_order;
  Bound higher_order;
};
constexpr ContactBound kContactBounds[] = {
    {"ramp_slide", {0.05, 1e-13}, {1e-9, 1e-13}},     // 0.0267 m; 1.5e-10 m (the oracle's own)
    {"disc_roll", {0.05, 1e-13}, {5e-10, 1e-13}},     // 0.0272 m; 6e-11 m
    {"static_friction", {2e-5, 1e-3}, {2e-5, 1e-3}},  // creeps 5.7e-6 m
    {"box_drop", {0.1, 10.0}, {5e-3, 0.5}},  // lands a step late (SE) or with slop: 4.4, 0.15 m/s
    {"stack3", {1e-11, 5e-10}, {1e-11, 5e-10}},   // 2.1e-12 m, 1.3e-10 m/s
    {"step_tip", {0.05, 0.1}, {0.03, 0.2}},       // 0.021 m; 0.008 m, 0.059 m/s
    {"heavy_stack", {1e-8, 1e-7}, {5e-9, 1e-7}},  // 3.4e-9 m; 1.4e-9 m, 2.4e-8 m/s
    // Set down at rest, pyramid6 is solved exactly at its first step (resting islands).
    {"pyramid6", {2.5e-10, 2.5e-9}, {2.5e-10, 2.5e-9}},  // 5.1e-11 m, 5.6e-10 m/s
};

// Why the exact rows' limit sits far above their figures.
constexpr const char* kExactReason =
    "exact in exact arithmetic: the figure is rounding and the oracle's own error, which vary "
    "with the platform; a fault on this path shows at first order, as symplectic Euler's 0.045 "
    "rad to 1.1 m on the scenes where it is not exact";

const ContactBound* contact_bound(std::string_view scene) {
  for (const auto& b : kContactBounds) {
    if (b.scene == scene) return &b;
  }
  return nullptr;
}

// How many of the output instants `times` ARKODE's cross-check of CVODE covers: all of them,
// but in a quick run (ctest's, also under the sanitizers) those of the first 0.1 s: its explicit
// steps cost pyramid6 16 s of CPU a simulated second, against CVODE's 0.3 s, and 28 times that
// under the sanitizers.
std::size_t cross_checked_instants(const std::vector<double>& times, bool quick) {
  constexpr double kQuickWindow = 0.1;  // s
  if (!quick) return times.size();
  const auto within = std::upper_bound(times.begin(), times.end(), kQuickWindow);
  return std::max<std::size_t>(2, static_cast<std::size_t>(within - times.begin()));
}

std::string ids_of(const Trajectory& reference) {
  return reference.impacts.empty() ? "IM:transMot IM:rotMot"
                                   : "IM:transMot IM:rotMot IM:col2D GD:impulse";
}

}  // namespace

std::vector<Check> accuracy_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                                   OracleReferences& references, CsvFiles& data) {
  CheckList list("accuracy against the oracle");
  std::ostringstream csv;
  csv << "scene,integrator,dt,position,orientation,velocity,angular_velocity,end_position,"
         "collision_time,unmatched_impacts\n";
  for (const auto& [name, original] : scenes) {
    Scene scene = original;
    if (o.quick) scene.duration = std::min(scene.duration, 1.0);
    if (o.progress) *o.progress << "  accuracy: " << name << "\n";
    const std::vector<double> times = output_instants(scene.duration, scene.dt);
    OracleOptions options = reference_options(scene);
    const auto reference = references.find(list, name, scene, times, options);
    if (!reference) continue;
    const Trajectory& cvode = reference->trajectory;
    const std::size_t crossed = cross_checked_instants(times, o.quick);
    Trajectory arkode;
    try {
      options.method = OracleMethod::ArkodeErk;
      arkode = run_oracle_trajectory(scene, std::span(times).first(crossed), options);
    } catch (const OracleDomainError& e) {
      cannot_run(list, name, "oracle (arkode-erk)", e.what());
      continue;
    }
    const Differences agree = compare(arkode, first_instants(cvode, crossed));
    const Scales scale = scales_of(cvode);
    const double position = agree.position / std::max(scale.position, 1.0);
    const double velocity = agree.velocity / std::max(scale.velocity, 1.0);
    list.within(name + ": ARKODE against CVODE", "NFR:Correctness",
                "position " + figure(position) + ", velocity " + figure(velocity) +
                    " (relative to the largest |p|, |v|, at least 1), t_c " +
                    figure(agree.collision_time) + " s, " +
                    std::to_string(agree.unmatched_impacts) +
                    " unmatched impacts, to t = " + figure(times[crossed - 1]) + " s",
                "all ≤ 1e-9, no unmatched impact",
                {{position, 1e-9},
                 {velocity, 1e-9},
                 {agree.collision_time, 1e-9},
                 {static_cast<double>(agree.unmatched_impacts), 0.0}},
                "1e-9 is the accuracy the oracle claims (docs/oracle.md), which this row "
                "establishes; two methods agreeing better is not asked of it");
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
      if (const ContactBound* contact = contact_bound(name)) {
        const Bound& bound =
            kind == IntegratorKind::SymplecticEuler ? contact->first_order : contact->higher_order;
        list.within(label, ids_of(cvode) + " IM:contact", measured,
                    "position ≤ " + figure(bound.position) + " m, velocity ≤ " +
                        figure(bound.velocity) +
                        " m/s (as measured: sequential impulses with slop are not exact)",
                    {{d.position, bound.position}, {d.velocity, bound.velocity}});
      } else if (exact_expected(scene, kind)) {
        list.within(label, ids_of(cvode), measured,
                    "position, velocity and t_c ≤ 1e-9, no unmatched impact",
                    {{d.position, 1e-9},
                     {d.velocity, 1e-9},
                     {d.collision_time, 1e-9},
                     {static_cast<double>(d.unmatched_impacts), 0.0}},
                    kExactReason);
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
