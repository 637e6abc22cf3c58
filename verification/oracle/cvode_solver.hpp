#pragma once
// The CVODE driver of the oracle: variable-order, variable-step linear multistep methods with
// root finding (cvode-adams, cvode-bdf).

#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <memory>
#include <type_traits>

#include "verification/oracle/ode_solver.hpp"

namespace gp::oracle {

class CvodeSolver final : public OdeSolver {
 public:
  enum class Family {
    /// Adams–Moulton, orders 1–12, solved by fixed-point iteration: the accurate choice for the
    /// non-stiff equations of rigid bodies.
    Adams,
    /// BDF, orders 1–5, solved by Newton's method on a dense difference-quotient Jacobian: a
    /// second, differently built method, and the one for stiff force models.
    Bdf,
  };

  CvodeSolver(Family family, const verification::OracleOptions& options, OdeProblem& problem,
              double t0, const double* y0);

  Stop advance(double t_stop, double& t) override;
  void restart(double t) override;
  bool projects() const override { return projects_; }
  long steps() const override;

 private:
  struct FreeMemory {
    void operator()(void* memory) const;
  };
  struct FreeMatrix {
    void operator()(SUNMatrix matrix) const;
  };
  struct FreeLinearSolver {
    void operator()(SUNLinearSolver solver) const;
  };
  struct FreeNonlinearSolver {
    void operator()(SUNNonlinearSolver solver) const;
  };

  // Declared in the order of creation, so that CVODE's memory, which uses the others, is freed
  // first.
  std::unique_ptr<std::remove_pointer_t<SUNMatrix>, FreeMatrix> matrix_;
  std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, FreeLinearSolver> linear_solver_;
  std::unique_ptr<std::remove_pointer_t<SUNNonlinearSolver>, FreeNonlinearSolver> nonlinear_solver_;
  std::unique_ptr<void, FreeMemory> memory_;
  long steps_before_restart_ = 0;  // CVodeReInit sets CVODE's own count back to 0
  bool projects_;

  /// (Re)initialises CVODE's root finding for the problem's root functions as armed now.
  void arm_roots();
};

}  // namespace gp::oracle
