#include "verification/oracle/oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "gamephysics/models/dd/angular_displacement.hpp"
#include "verification/oracle/collision_watch.hpp"
#include "verification/oracle/ode_problem.hpp"
#include "verification/oracle/ode_solver.hpp"
#include "verification/oracle/ode_system.hpp"
#include "verification/oracle/zeno_guard.hpp"

namespace gp::verification {

namespace {

constexpr std::array<std::pair<OracleMethod, std::string_view>, 3> kMethodNames{{
    {OracleMethod::CvodeAdams, "cvode-adams"},
    {OracleMethod::CvodeBdf, "cvode-bdf"},
    {OracleMethod::ArkodeErk, "arkode-erk"},
}};

void validate(const OracleOptions& o, std::span<const double> times, double t0) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(o.rtol)) throw std::invalid_argument("oracle: rtol must be finite and > 0");
  if (!positive(o.atol)) throw std::invalid_argument("oracle: atol must be finite and > 0");
  if (!positive(o.contact_tolerance)) {
    throw std::invalid_argument("oracle: contact_tolerance must be finite and > 0");
  }
  if (o.max_events < 1 || o.zeno_events < 2 || !(o.zeno_window >= 0.0) || o.max_steps < 1) {
    throw std::invalid_argument(
        "oracle: max_events >= 1, zeno_events >= 2, zeno_window >= 0 and max_steps >= 1 needed");
  }
  double previous = t0;
  for (double t : times) {
    if (!std::isfinite(t) || t < previous) {
      throw std::invalid_argument(
          "oracle: output times must be finite, non-decreasing and not before the space's time");
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

std::vector<BodyState> report(const MotionState& s) {
  std::vector<BodyState> states;
  states.reserve(s.position.size());
  for (std::size_t j = 0; j < s.position.size(); ++j) {
    // y carries ϕ unreduced; the SRS output constraint wants it in [0, 2π).
    states.push_back({s.position[j], dd::rotated_orientation(s.angle[j], 0.0), s.velocity[j],
                      s.angular_velocity[j]});
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

OracleResult run_oracle(const Space& space, std::span<const double> output_times,
                        const OracleOptions& options) {
  const double t0 = space.time();
  validate(options, output_times, t0);
  OdeSystem system(space);
  CollisionWatch watch(space, options);
  ZenoGuard zeno(options);
  OracleResult result;
  result.times.assign(output_times.begin(), output_times.end());

  std::vector<double> y(system.size());
  system.initial_values(y.data());
  MotionState s;
  Accelerations a;
  system.state_at(t0, y.data(), s);
  system.accelerations(t0, s, a);
  watch.require_clear(t0, s, a, "at the start");
  if (system.size() == 0) {
    // Nothing dynamic: every body moves in closed form, and nothing can collide.
    for (double t : output_times) {
      system.state_at(t, y.data(), s);
      result.states.push_back(report(s));
    }
    return result;
  }

  OdeProblem problem(system, watch);
  const auto solver = make_ode_solver(options, problem, t0, y.data());
  double t = t0;
  for (double t_out : output_times) {
    while (!reached(t, t_out)) {
      system.state_at(t, solver->values(), s);
      system.accelerations(t, s, a);
      const double t_stop = std::min(t_out, t + std::max(watch.horizon(s, a), kLeastStep * t));
      if (solver->advance(t_stop, t) == OdeSolver::Stop::Reached) continue;
      system.state_at(t, solver->values(), s);
      const std::size_t first_new = result.events.size();
      watch.resolve(t, solver->crossed(), s, result.events);
      for (std::size_t k = first_new; k < result.events.size(); ++k) {
        zeno.record(t, describe_pair(space, result.events[k].body_a, result.events[k].body_b));
      }
      system.accelerations(t, s, a);
      watch.require_clear(t, s, a, "after an impact");
      system.values_of(s, solver->values());
      solver->restart(t);
    }
    system.state_at(t_out, solver->values(), s);
    watch.require_apart(t_out, s);
    result.states.push_back(report(s));
  }
  result.steps = solver->steps();
  return result;
}

}  // namespace gp::verification
