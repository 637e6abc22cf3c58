#pragma once
// What a SUNDIALS solver calls back: the right-hand side f(t, y) of the hybrid system, its root
// functions g(t, y) (the event watch), and the projection onto the active contacts. CVODE and
// ARKODE take callbacks of the same C signatures, with the problem as their user data.

#include <sundials/sundials_nvector.h>

#include <exception>

#include "verification/oracle/hybrid/event_watch.hpp"
#include "verification/oracle/hybrid/hybrid_system.hpp"

namespace gp::oracle {

class OdeProblem {
 public:
  /// Both must outlive the problem.
  OdeProblem(HybridSystem& system, EventWatch& watch) : system_(system), watch_(watch) {}

  std::size_t size() const { return system_.size(); }
  /// The number of root functions, as the watch is armed now.
  int root_count() const { return static_cast<int>(watch_.size()); }

  /// CVRhsFn / ARKRhsFn: f(t, y) into ydot; `problem` is this.
  static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* problem);
  /// CVRootFn / ARKRootFn: the watch's root functions into g.
  static int roots(sunrealtype t, N_Vector y, sunrealtype* g, void* problem);
  /// CVProjFn: the correction that puts y onto the active contacts' constraints.
  static int project(sunrealtype t, N_Vector y, N_Vector correction, sunrealtype tolerance,
                     N_Vector error, void* problem);
  /// ARKPostProcessFn: y put onto the active contacts' constraints after each step.
  static int project_in_place(sunrealtype t, N_Vector y, void* problem);

  /// SUNDIALS is C: nothing may unwind through it. An exception thrown inside a callback is
  /// kept, the callback reports an unrecoverable failure, and the solver driver calls this to
  /// rethrow it once SUNDIALS has returned.
  void rethrow_pending();

 private:
  HybridSystem& system_;
  EventWatch& watch_;
  Snapshot snapshot_;  // scratch for roots()
  std::exception_ptr pending_;
};

}  // namespace gp::oracle
