#pragma once
// The oracle's solution of a scene in the suite's terms.

#include <span>

#include "verification/oracle/oracle.hpp"
#include "verification/suite/trajectory.hpp"

namespace gp::verification {

/// The scene integrated by the SUNDIALS oracle to the given instants [s]. Throws
/// OracleDomainError for a scene outside the oracle's domain.
Trajectory run_oracle_trajectory(const Scene& scene, std::span<const double> times,
                                 const OracleOptions& options);

}  // namespace gp::verification
