#pragma once
// The ARKODE driver of the oracle: an explicit Runge–Kutta pair with adaptive steps and root
// finding (arkode-erk), a one-step method independent of CVODE's multistep ones.

#include <memory>

#include "verification/oracle/ode_solver.hpp"

namespace gp::verification {

class ArkodeSolver final : public OdeSolver {
 public:
  /// ERKStep with the Verner 8(5)6 table: 8 stages, order 6 with an embedded order-5 error
  /// estimate. Order 6 rather than Fehlberg's 8 because roots and restart states come from
  /// ARKODE's Hermite interpolant, of degree at most 5: a higher-order method would take steps
  /// too long for it.
  ArkodeSolver(const OracleOptions& options, OdeProblem& problem, double t0, const double* y0);

  Stop advance(double t_stop, double& t) override;
  void restart(double t) override;
  long steps() const override;

 private:
  struct FreeMemory {
    void operator()(void* memory) const;
  };

  std::unique_ptr<void, FreeMemory> memory_;
  long steps_before_restart_ = 0;  // ERKStepReInit sets ARKODE's own count back to 0
};

}  // namespace gp::verification
