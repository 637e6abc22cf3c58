#include "verification/oracle/ode_problem.hpp"

#include <nvector/nvector_serial.h>

#include <utility>

namespace gp::verification {

namespace {
// SUNDIALS: a negative return from a callback is an unrecoverable failure.
constexpr int kUnrecoverable = -1;
}  // namespace

int OdeProblem::rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* problem) {
  auto& self = *static_cast<OdeProblem*>(problem);
  try {
    self.system_.derivative(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    return 0;
  } catch (...) {
    self.pending_ = std::current_exception();
    return kUnrecoverable;
  }
}

int OdeProblem::roots(sunrealtype t, N_Vector y, sunrealtype* g, void* problem) {
  auto& self = *static_cast<OdeProblem*>(problem);
  try {
    self.system_.state_at(t, N_VGetArrayPointer(y), self.state_);
    self.watch_.distances(self.state_, g);
    return 0;
  } catch (...) {
    self.pending_ = std::current_exception();
    return kUnrecoverable;
  }
}

void OdeProblem::rethrow_pending() {
  if (pending_) std::rethrow_exception(std::exchange(pending_, nullptr));
}

}  // namespace gp::verification
