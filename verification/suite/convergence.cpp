// Observed order of convergence of each game integrator by step halving on a smooth scene (the
// two-body orbit: forces that change along the path), against the oracle.
#include <cmath>
#include <sstream>

#include "verification/bench/formatted.hpp"
#include "verification/suite/oracle_domain.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

namespace {

constexpr double kCoarsestStep = 0.04;  // s

}  // namespace

std::vector<Check> convergence_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                                      CsvFiles& data) {
  CheckList list("order of convergence");
  std::ostringstream csv;
  csv << "scene,integrator,dt,position_error\n";
  for (const auto& [name, original] : scenes) {
    if (!original.settings.G) continue;  // the smooth scenes: forces vary along the path
    Scene scene = original;
    if (o.quick) scene.duration = std::min(scene.duration, 1.0);
    if (o.progress) *o.progress << "  convergence: " << name << "\n";
    OracleOptions options;
    options.rtol = options.atol = 1e-13;
    // The error is the largest over common instants, multiples of the coarsest step: the error
    // at one instant can vanish by chance (a phase error that comes round again).
    std::vector<double> instants;
    for (double t = 0.0; t < scene.duration - 1e-9; t += kCoarsestStep) instants.push_back(t);
    instants.push_back(scene.duration);
    const auto solved = oracle_reference(list, name, scene, instants, options);
    if (!solved) continue;
    const Trajectory& reference = solved->trajectory;
    const struct {
      IntegratorKind kind;
      double order;
    } expected[] = {{IntegratorKind::SymplecticEuler, 1.0},
                    {IntegratorKind::VelocityVerlet, 2.0},
                    {IntegratorKind::RK4, 4.0}};
    for (const auto& [kind, nominal] : expected) {
      std::vector<double> errors;
      std::string measured;
      for (int k = 0; k < 4; ++k) {
        // Steps coarse enough that even RK4's error stays far above the oracle's.
        const double dt = kCoarsestStep / std::pow(2.0, k);
        errors.push_back(
            compare(sample_at(run_engine(scene, kind, dt), instants), reference).position);
        csv << name << "," << integrator_name(kind) << "," << dt << "," << errors.back() << "\n";
        measured += (k ? ", " : "largest position error ") + figure(errors.back());
      }
      // The finest halving whose errors are still well above the oracle's own error.
      double order = std::log2(errors[0] / errors[1]);
      for (int k = 1; k + 1 < 4; ++k) {
        if (errors[k + 1] > 1e-9) order = std::log2(errors[k] / errors[k + 1]);
      }
      list.within(name + ", " + std::string(integrator_name(kind)) +
                      ", dt = " + figure(kCoarsestStep) + " s halved 3 times",
                  "LC:Variable-ODE-Solver IM:transMot",
                  measured + " m; observed order " + bench::formatted("%.4f", order),
                  "order within 0.05 of " + figure(nominal), {{std::abs(order - nominal), 0.05}},
                  "the figure is the order's distance from its nominal value, which the "
                  "asymptotic regime makes small; 0.05 tells it from the next order by 20×");
    }
  }
  data.emplace_back("convergence.csv", csv.str());
  return list.rows();
}

}  // namespace gp::verification
