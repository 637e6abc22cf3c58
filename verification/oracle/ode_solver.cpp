#include "verification/oracle/ode_solver.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "verification/oracle/arkode_solver.hpp"
#include "verification/oracle/cvode_solver.hpp"

namespace gp::oracle {

using verification::OracleDomainError;
using verification::OracleMethod;
using verification::OracleOptions;

OdeSolver::OdeSolver(OdeProblem& problem, const double* y0, std::string name, long max_steps)
    : problem_(problem),
      y_(problem.size(), context_.get()),
      name_(std::move(name)),
      max_steps_(max_steps) {
  std::copy_n(y0, problem.size(), y_.data());
  size_roots();
}

void OdeSolver::size_roots() {
  crossed_.assign(static_cast<std::size_t>(problem_.root_count()), 0);
  directions_.assign(crossed_.size(), -1);
}

void OdeSolver::after_step(double t) {
  problem_.rethrow_pending();
  if (steps() > max_steps_) {
    fail("more than max_steps = " + std::to_string(max_steps_) + " steps", t);
  }
}

void OdeSolver::keep_error(int code, const char* module, const char* function, char* message,
                           void* solver) {
  if (code > 0) return;
  static_cast<OdeSolver*>(solver)->error_ = std::string(module) + "::" + function + ": " + message;
}

void OdeSolver::fail(const std::string& flag_name, double t) {
  problem_.rethrow_pending();
  throw OracleDomainError("the solver " + name_ + " failed with " + flag_name +
                              (error_.empty() ? "" : " (" + error_ + ")"),
                          t);
}

void OdeSolver::check(int flag, const char* call) const {
  if (flag < 0) {
    throw std::runtime_error("SUNDIALS " + std::string(call) + " failed (flag " +
                             std::to_string(flag) + ")" + (error_.empty() ? "" : ": " + error_));
  }
}

std::unique_ptr<OdeSolver> make_ode_solver(const OracleOptions& options, OdeProblem& problem,
                                           double t0, const double* y0) {
  switch (options.method) {
    case OracleMethod::CvodeAdams:
      return std::make_unique<CvodeSolver>(CvodeSolver::Family::Adams, options, problem, t0, y0);
    case OracleMethod::CvodeBdf:
      return std::make_unique<CvodeSolver>(CvodeSolver::Family::Bdf, options, problem, t0, y0);
    case OracleMethod::ArkodeErk:
      return std::make_unique<ArkodeSolver>(options, problem, t0, y0);
    case OracleMethod::TimeStepping:
      break;  // no ODE: run_oracle steps the scene itself
  }
  throw std::invalid_argument("unknown oracle method");
}

}  // namespace gp::oracle
