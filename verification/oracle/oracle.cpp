#include "verification/oracle/oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "gamephysics/models/dd/angular_displacement.hpp"
#include "verification/oracle/hybrid/contact_events.hpp"
#include "verification/oracle/model/world.hpp"
#include "verification/oracle/ode_problem.hpp"
#include "verification/oracle/ode_solver.hpp"
#include "verification/oracle/stepping/time_stepping.hpp"
#include "verification/oracle/zeno_guard.hpp"

namespace gp::verification {

namespace {

constexpr std::array<std::pair<OracleMethod, std::string_view>, 4> kMethodNames{{
    {OracleMethod::CvodeAdams, "cvode-adams"},
    {OracleMethod::CvodeBdf, "cvode-bdf"},
    {OracleMethod::ArkodeErk, "arkode-erk"},
    {OracleMethod::TimeStepping, "time-stepping"},
}};

void validate(const OracleOptions& o, std::span<const double> times) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(o.rtol)) throw std::invalid_argument("oracle: rtol must be finite and > 0");
  if (!positive(o.atol)) throw std::invalid_argument("oracle: atol must be finite and > 0");
  if (!positive(o.contact_tolerance) || !positive(o.rest_speed) || !positive(o.speed_tolerance) ||
      !positive(o.step)) {
    throw std::invalid_argument(
        "oracle: contact_tolerance, rest_speed, speed_tolerance and step must be finite and > 0");
  }
  if (o.max_events < 1 || o.zeno_events < 2 || !(o.zeno_window >= 0.0) || o.max_steps < 1) {
    throw std::invalid_argument(
        "oracle: max_events >= 1, zeno_events >= 2, zeno_window >= 0 and max_steps >= 1 needed");
  }
  double previous = 0.0;
  for (double t : times) {
    if (!std::isfinite(t) || t < previous) {
      throw std::invalid_argument(
          "oracle: output times must be finite, non-decreasing and not before 0");
    }
    previous = t;
  }
}

// The solver cannot take a step shorter than rounding allows (CVODE refuses "tout too close to
// t0"): an instant this close to where the solution is counts as reached, and no stop is set
// closer than kLeastStep·t.
constexpr double kLeastStep = 16.0 * std::numeric_limits<double>::epsilon();

bool reached(double t, double target) {
  return target - t <=
         4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t), std::abs(target));
}

std::vector<BodyState> report(std::span<const oracle::Motion> motions) {
  std::vector<BodyState> states;
  states.reserve(motions.size());
  for (const oracle::Motion& m : motions) {
    // y carries ϕ unreduced; the SRS output constraint wants it in [0, 2π).
    states.push_back(
        {m.position, dd::rotated_orientation(m.angle, 0.0), m.velocity, m.angular_velocity});
  }
  return states;
}

}  // namespace

std::string_view oracle_method_name(OracleMethod method) {
  for (const auto& [m, name] : kMethodNames) {
    if (m == method) return name;
  }
  return "unknown";
}

std::optional<OracleMethod> oracle_method_from_name(std::string_view name) {
  for (const auto& [m, n] : kMethodNames) {
    if (n == name) return m;
  }
  return std::nullopt;
}

OracleResult run_oracle(const Scene& scene, std::span<const double> output_times,
                        const OracleOptions& options) {
  validate(options, output_times);
  const oracle::World world = oracle::build_world(scene);
  oracle::EventWatch watch(world, options.contact_tolerance, options.speed_tolerance);
  if (options.method == OracleMethod::TimeStepping) {
    const oracle::SteppedRun run = oracle::time_stepping(world, watch.pairs(), output_times,
                                                         options.step, options.contact_tolerance);
    OracleResult result;
    result.times.assign(output_times.begin(), output_times.end());
    for (const auto& motions : run.motions) result.states.push_back(report(motions));
    result.steps = run.steps;
    result.largest_drift = run.deepest_overlap;
    return result;
  }
  oracle::HybridSystem system(world);
  oracle::ContactEvents contacts(system, watch, options);
  oracle::ZenoGuard zeno(options);
  OracleResult result;
  result.times.assign(output_times.begin(), output_times.end());
  std::vector<oracle::Motion> motions(system.states().body_count());

  std::vector<double> y(system.size());
  system.states().initial_values(y.data());
  double t = 0.0;
  contacts.start(t, y.data(), result.events);
  system.states().motions_at(t, y.data(), motions);
  watch.arm(system.contacts(), motions);
  if (system.size() == 0) {
    // Nothing dynamic: every body moves in closed form, and nothing can collide.
    for (double t_out : output_times) {
      system.states().motions_at(t_out, y.data(), motions);
      result.states.push_back(report(motions));
    }
    return result;
  }

  oracle::OdeProblem problem(system, watch);
  const auto solver = oracle::make_ode_solver(options, problem, t, y.data());
  oracle::Snapshot snapshot;
  for (double t_out : output_times) {
    while (!reached(t, t_out)) {
      system.evaluate(t, solver->values(), snapshot);
      contacts.require_pushing(snapshot);
      const double t_stop = std::min(t_out, t + std::max(watch.horizon(snapshot), kLeastStep * t));
      if (solver->advance(t_stop, t) == oracle::OdeSolver::Stop::Reached) {
        if (!solver->projects() && !system.contacts().empty()) {
          system.project(t, solver->values());
          solver->restart(t);
        }
        continue;
      }
      const std::size_t first_new = result.events.size();
      contacts.handle(t, solver->values(), solver->crossed(), result.events);
      // One count per event, simultaneous impacts included; changes of contact without an
      // impact can chatter too (stick, slip, stick, ...).
      if (first_new == result.events.size()) {
        zeno.record(t, "a change of contact");
        ++result.contact_changes;
      } else {
        const OracleEvent& e = result.events[first_new];
        zeno.record(t, "an impact of " + contacts.describe(e.body_a, e.body_b));
      }
      system.states().motions_at(t, solver->values(), motions);
      watch.arm(system.contacts(), motions);
      solver->restart(t);
    }
    contacts.require_apart(t_out, solver->values());
    system.evaluate(t_out, solver->values(), snapshot);
    contacts.require_pushing(snapshot);
    contacts.note_drift(t_out, solver->values());
    system.states().motions_at(t_out, solver->values(), motions);
    result.states.push_back(report(motions));
  }
  result.steps = solver->steps();
  result.largest_drift = contacts.largest_drift();
  return result;
}

}  // namespace gp::verification
