#pragma once
// The ARKODE driver of the oracle: an explicit Runge–Kutta pair with adaptive steps and root
// finding (arkode-erk), a one-step method independent of CVODE's multistep ones.

#include <memory>

#include "verification/oracle/ode_solver.hpp"

namespace gp::oracle {

class ArkodeSolver final : public OdeSolver {
 public:
  /// ERKStep with the Fehlberg 13(7)8 table: 13 stages, order 8 with an embedded order-7 error
  /// estimate. Verner's 8(5)6 (order 6) drifted 6e-9 m from the closed-form orbit in 7 s at
  /// rtol 1e-14, Fehlberg 9e-14 m; event times still agree with CVODE to 1e-11 s.
  ArkodeSolver(const verification::OracleOptions& options, OdeProblem& problem, double t0,
               const double* y0);

  Stop advance(double t_stop, double& t) override;
  void restart(double t) override;
  bool projects() const override { return true; }
  long steps() const override;

 private:
  struct FreeMemory {
    void operator()(void* memory) const;
  };

  std::unique_ptr<void, FreeMemory> memory_;
  long steps_before_restart_ = 0;  // ERKStepReInit sets ARKODE's own count back to 0

  /// (Re)initialises ARKODE's root finding for the problem's root functions as armed now.
  void arm_roots();
};

}  // namespace gp::oracle
