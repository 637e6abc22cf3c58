#include "verification/oracle/arkode_solver.hpp"

#include <arkode/arkode_erkstep.h>

#include <cstdlib>
#include <new>

namespace gp::oracle {

using verification::OracleOptions;

namespace {

constexpr double kMaxStep = 1e-3;  // s

}  // namespace

void ArkodeSolver::FreeMemory::operator()(void* memory) const {
  ERKStepFree(&memory);
}

ArkodeSolver::ArkodeSolver(const OracleOptions& options, OdeProblem& problem, double t0,
                           const double* y0)
    : OdeSolver(problem, y0, "arkode-erk", options.max_steps) {
  void* memory = ERKStepCreate(OdeProblem::rhs, t0, y_.get(), context_.get());
  if (memory == nullptr) throw std::bad_alloc();
  memory_.reset(memory);
  check(ERKStepSetErrHandlerFn(memory, keep_error, this), "ERKStepSetErrHandlerFn");
  check(ERKStepSetTableNum(memory, ARKODE_FEHLBERG_13_7_8), "ERKStepSetTableNum");
  check(ERKStepSetUserData(memory, &problem), "ERKStepSetUserData");
  // Roots are located on the dense output between steps, a Hermite interpolant. Over the 8 ms
  // steps the order-8 pair takes in contact scenes it put a stick-to-slip event 6e-9 s off
  // CVODE's (step_tip); at most 1 ms it is exact to 1e-12 s.
  check(ERKStepSetMaxStep(memory, kMaxStep), "ERKStepSetMaxStep");
  check(ERKStepSStolerances(memory, options.rtol, options.atol), "ERKStepSStolerances");
  check(ERKStepSetPostprocessStepFn(memory, OdeProblem::project_in_place),
        "ERKStepSetPostprocessStepFn");
  arm_roots();
}

void ArkodeSolver::arm_roots() {
  size_roots();
  check(ERKStepRootInit(memory_.get(), problem_.root_count(), OdeProblem::roots),
        "ERKStepRootInit");
  if (problem_.root_count() == 0) return;
  check(ERKStepSetRootDirection(memory_.get(), directions_.data()), "ERKStepSetRootDirection");
  // A root function just crossed starts at ~0: expected, not worth a warning.
  check(ERKStepSetNoInactiveRootWarn(memory_.get()), "ERKStepSetNoInactiveRootWarn");
}

OdeSolver::Stop ArkodeSolver::advance(double t_stop, double& t) {
  check(ERKStepSetStopTime(memory_.get(), t_stop), "ERKStepSetStopTime");
  int flag = ARK_SUCCESS;
  do {
    // One step at a time, to stop at once when a callback failed (as CvodeSolver::advance).
    flag = ERKStepEvolve(memory_.get(), t_stop, y_.get(), &t, ARK_ONE_STEP);
    after_step(t);
  } while (flag == ARK_SUCCESS && t < t_stop);
  if (flag < 0) {
    const std::unique_ptr<char, decltype(&std::free)> name(ERKStepGetReturnFlagName(flag),
                                                           &std::free);
    fail(name ? name.get() : std::to_string(flag), t);
  }
  if (flag != ARK_ROOT_RETURN) return Stop::Reached;
  check(ERKStepGetRootInfo(memory_.get(), crossed_.data()), "ERKStepGetRootInfo");
  return Stop::Root;
}

void ArkodeSolver::restart(double t) {
  steps_before_restart_ = steps();
  check(ERKStepReInit(memory_.get(), OdeProblem::rhs, t, y_.get()), "ERKStepReInit");
  arm_roots();
}

long ArkodeSolver::steps() const {
  long count = 0;
  ERKStepGetNumSteps(memory_.get(), &count);
  return steps_before_restart_ + count;
}

}  // namespace gp::oracle
