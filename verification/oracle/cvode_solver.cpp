#include "verification/oracle/cvode_solver.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_proj.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cstdlib>
#include <new>

namespace gp::oracle {

using verification::OracleOptions;

void CvodeSolver::FreeMemory::operator()(void* memory) const {
  CVodeFree(&memory);
}
void CvodeSolver::FreeMatrix::operator()(SUNMatrix matrix) const {
  SUNMatDestroy(matrix);
}
void CvodeSolver::FreeLinearSolver::operator()(SUNLinearSolver solver) const {
  SUNLinSolFree(solver);
}
void CvodeSolver::FreeNonlinearSolver::operator()(SUNNonlinearSolver solver) const {
  SUNNonlinSolFree(solver);
}

CvodeSolver::CvodeSolver(Family family, const OracleOptions& options, OdeProblem& problem,
                         double t0, const double* y0)
    : OdeSolver(problem, y0, family == Family::Adams ? "cvode-adams" : "cvode-bdf",
                options.max_steps),
      projects_(family == Family::Bdf) {
  void* memory = CVodeCreate(family == Family::Adams ? CV_ADAMS : CV_BDF, context_.get());
  if (memory == nullptr) throw std::bad_alloc();
  memory_.reset(memory);
  check(CVodeSetErrHandlerFn(memory, keep_error, this), "CVodeSetErrHandlerFn");
  check(CVodeInit(memory, OdeProblem::rhs, t0, y_.get()), "CVodeInit");
  check(CVodeSetUserData(memory, &problem), "CVodeSetUserData");
  check(CVodeSStolerances(memory, options.rtol, options.atol), "CVodeSStolerances");
  if (family == Family::Adams) {
    nonlinear_solver_.reset(SUNNonlinSol_FixedPoint(y_.get(), 0, context_.get()));
    if (!nonlinear_solver_) throw std::bad_alloc();
    check(CVodeSetNonlinearSolver(memory, nonlinear_solver_.get()), "CVodeSetNonlinearSolver");
  } else {
    const auto n = static_cast<sunindextype>(problem.size());
    matrix_.reset(SUNDenseMatrix(n, n, context_.get()));
    if (!matrix_) throw std::bad_alloc();
    linear_solver_.reset(SUNLinSol_Dense(y_.get(), matrix_.get(), context_.get()));
    if (!linear_solver_) throw std::bad_alloc();
    check(CVodeSetLinearSolver(memory, linear_solver_.get(), matrix_.get()),
          "CVodeSetLinearSolver");
  }
  if (projects_) {
    check(CVodeSetProjFn(memory, OdeProblem::project), "CVodeSetProjFn");
    // The correction is exact to round-off, so the error estimate needs no projecting.
    check(CVodeSetProjErrEst(memory, SUNFALSE), "CVodeSetProjErrEst");
  }
  arm_roots();
}

void CvodeSolver::arm_roots() {
  size_roots();
  check(CVodeRootInit(memory_.get(), problem_.root_count(), OdeProblem::roots), "CVodeRootInit");
  if (problem_.root_count() == 0) return;
  check(CVodeSetRootDirection(memory_.get(), directions_.data()), "CVodeSetRootDirection");
  // A root function just crossed starts at ~0: expected, not worth a warning.
  check(CVodeSetNoInactiveRootWarn(memory_.get()), "CVodeSetNoInactiveRootWarn");
}

OdeSolver::Stop CvodeSolver::advance(double t_stop, double& t) {
  check(CVodeSetStopTime(memory_.get(), t_stop), "CVodeSetStopTime");
  int flag = CV_SUCCESS;
  do {
    // One step at a time, to stop at once when a callback failed: CVODE's fixed-point iteration
    // takes a failed right-hand side for a convergence failure and retries with ever shorter
    // steps, closing in on the failing instant until it runs out of steps.
    flag = CVode(memory_.get(), t_stop, y_.get(), &t, CV_ONE_STEP);
    after_step(t);
  } while (flag == CV_SUCCESS && t < t_stop);
  if (flag < 0) {
    const std::unique_ptr<char, decltype(&std::free)> name(CVodeGetReturnFlagName(flag),
                                                           &std::free);
    fail(name ? name.get() : std::to_string(flag), t);
  }
  if (flag != CV_ROOT_RETURN) return Stop::Reached;
  check(CVodeGetRootInfo(memory_.get(), crossed_.data()), "CVodeGetRootInfo");
  return Stop::Root;
}

void CvodeSolver::restart(double t) {
  steps_before_restart_ = steps();
  check(CVodeReInit(memory_.get(), t, y_.get()), "CVodeReInit");
  arm_roots();
}

long CvodeSolver::steps() const {
  long count = 0;
  CVodeGetNumSteps(memory_.get(), &count);
  return steps_before_restart_ + count;
}

}  // namespace gp::oracle
