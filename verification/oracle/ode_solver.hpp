#pragma once
// One interface over the SUNDIALS integrators the oracle offers (OracleMethod), so that the
// event loop of run_oracle is written once: advance to a stop time or to the first root, read
// which root functions crossed zero, restart after an impulse.

#include <memory>
#include <string>
#include <vector>

#include "verification/oracle/ode_problem.hpp"
#include "verification/oracle/oracle.hpp"
#include "verification/oracle/sundials_handles.hpp"

namespace gp::oracle {

class OdeSolver {
 public:
  enum class Stop {
    Reached,  ///< at the stop time
    Root,     ///< at an earlier zero crossing of a root function (an impact)
  };

  virtual ~OdeSolver() = default;
  OdeSolver(const OdeSolver&) = delete;
  OdeSolver& operator=(const OdeSolver&) = delete;

  /// The solution y where the last advance stopped; write it before restart().
  double* values() const { return y_.data(); }

  /// Integrates from the current time towards `t_stop` [s], never past it, and returns where it
  /// stopped: at `t_stop`, or at the first root on the way, with its time in `t` and the solution
  /// there in values(). Only crossings from above (a distance falling to zero) count. Throws
  /// OracleDomainError when the solver fails, or what a callback threw.
  virtual Stop advance(double t_stop, double& t) = 0;

  /// Per root function: non-zero when it crossed zero at the last Root stop.
  const std::vector<int>& crossed() const { return crossed_; }

  /// Starts afresh at time t [s] from values() (velocities changed by an impulse, which the
  /// solver's history must not smooth over), with the problem's root functions as armed now.
  virtual void restart(double t) = 0;

  /// True when the solver puts its solution onto the active contacts after every step (CVODE's
  /// projection, BDF only; ARKODE's post-step function); false for Adams, whose solution the
  /// driver projects where it stops.
  virtual bool projects() const = 0;

  /// Steps taken since the start [1].
  virtual long steps() const = 0;

 protected:
  /// The solver starts from y0 (problem.size() values); `name` names it in messages.
  OdeSolver(OdeProblem& problem, const double* y0, std::string name, long max_steps);

  /// Sizes the root bookkeeping for the problem's root functions as armed now.
  void size_roots();

  /// After each step: rethrows what a callback threw, and fails beyond max_steps steps.
  void after_step(double t);

  /// A SUNDIALS error handler (CVErrHandlerFn and ARKErrHandlerFn alike), `solver` being this:
  /// keeps the message of an error for the OracleDomainError rather than let SUNDIALS print it;
  /// warnings (positive codes) are dropped.
  static void keep_error(int code, const char* module, const char* function, char* message,
                         void* solver);

  /// Rethrows what a callback threw, else throws OracleDomainError for the solver's failure
  /// `flag_name` at time t [s].
  [[noreturn]] void fail(const std::string& flag_name, double t);

  /// Throws std::runtime_error when a SUNDIALS setup call named `call` returned `flag` < 0.
  void check(int flag, const char* call) const;

  SundialsContext context_;  // first: the SUNDIALS objects of the derived solvers go before it
  OdeProblem& problem_;
  SerialVector y_;
  std::vector<int> crossed_;
  std::vector<int> directions_;  // -1 per root function: only falling ones count
  std::string name_;
  long max_steps_;
  std::string error_;
};

/// The solver of options.method with options' tolerances and step limit, at t0 [s] from y0.
std::unique_ptr<OdeSolver> make_ode_solver(const verification::OracleOptions& options,
                                           OdeProblem& problem, double t0, const double* y0);

}  // namespace gp::oracle
