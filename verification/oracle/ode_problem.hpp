#pragma once
// What a SUNDIALS solver calls back: the right-hand side f(t, y) and the root functions g(t, y)
// (one signed distance per watched pair of shapes). CVODE and ARKODE take callbacks of the same
// C signatures, with the problem as their user data.

#include <sundials/sundials_nvector.h>

#include <exception>

#include "verification/oracle/collision_watch.hpp"
#include "verification/oracle/ode_system.hpp"

namespace gp::verification {

class OdeProblem {
 public:
  /// Both must outlive the problem.
  OdeProblem(OdeSystem& system, CollisionWatch& watch) : system_(system), watch_(watch) {}

  std::size_t size() const { return system_.size(); }
  int root_count() const { return static_cast<int>(watch_.size()); }

  /// CVRhsFn / ARKRhsFn: f(t, y) into ydot; `problem` is this.
  static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* problem);
  /// CVRootFn / ARKRootFn: the signed distance of every watched pair into g.
  static int roots(sunrealtype t, N_Vector y, sunrealtype* g, void* problem);

  /// SUNDIALS is C: nothing may unwind through it. An exception thrown inside a callback (by a
  /// user's force callback, say) is kept, the callback reports an unrecoverable failure, and the
  /// solver driver calls this to rethrow it once SUNDIALS has returned.
  void rethrow_pending();

 private:
  OdeSystem& system_;
  CollisionWatch& watch_;
  MotionState state_;  // scratch for roots()
  std::exception_ptr pending_;
};

}  // namespace gp::verification
