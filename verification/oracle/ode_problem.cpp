#include "verification/oracle/ode_problem.hpp"

#include <nvector/nvector_serial.h>

#include <algorithm>
#include <utility>

namespace gp::oracle {

namespace {

// SUNDIALS: a negative return from a callback is an unrecoverable failure.
constexpr int kUnrecoverable = -1;

template <typename Body>
int guarded(std::exception_ptr& pending, Body body) {
  try {
    body();
    return 0;
  } catch (...) {
    pending = std::current_exception();
    return kUnrecoverable;
  }
}

}  // namespace

int OdeProblem::rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* problem) {
  auto& self = *static_cast<OdeProblem*>(problem);
  return guarded(self.pending_, [&] {
    self.system_.derivative(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  });
}

int OdeProblem::roots(sunrealtype t, N_Vector y, sunrealtype* g, void* problem) {
  auto& self = *static_cast<OdeProblem*>(problem);
  return guarded(self.pending_, [&] {
    self.system_.evaluate(t, N_VGetArrayPointer(y), self.snapshot_);
    self.watch_.evaluate(self.snapshot_, self.system_.contacts(), g);
  });
}

int OdeProblem::project(sunrealtype t, N_Vector y, N_Vector correction, sunrealtype, N_Vector,
                        void* problem) {
  auto& self = *static_cast<OdeProblem*>(problem);
  return guarded(self.pending_, [&] {
    const double* from = N_VGetArrayPointer(y);
    double* to = N_VGetArrayPointer(correction);
    std::copy_n(from, self.size(), to);
    self.system_.project(t, to);
    for (std::size_t i = 0; i < self.size(); ++i) to[i] -= from[i];
  });
}

int OdeProblem::project_in_place(sunrealtype t, N_Vector y, void* problem) {
  auto& self = *static_cast<OdeProblem*>(problem);
  return guarded(self.pending_, [&] { self.system_.project(t, N_VGetArrayPointer(y)); });
}

void OdeProblem::rethrow_pending() {
  if (pending_) std::rethrow_exception(std::exchange(pending_, nullptr));
}

}  // namespace gp::oracle
