#pragma once
// The shipped scenes declared outside the oracle's domain, each with its reason, and the one way
// every section of `verify` obtains an oracle reference: a declared scene is reported with its
// reason and never run; any other scene that leaves the domain fails the run. Each reference
// carries the oracle's own error estimate (the scene re-solved at 100× tighter tolerances) and
// its cost.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "verification/oracle/oracle.hpp"
#include "verification/suite/check.hpp"
#include "verification/suite/trajectory.hpp"

namespace gp::verification {

/// Why the oracle does not run the shipped scene or hard case `name`, or nothing when it is in
/// the domain.
std::optional<std::string_view> outside_oracle_domain(std::string_view name);

/// Why the trajectories of the shipped scene `name` are not compared with the oracle's (a chaotic
/// pile, whose well-posed measures the pile section compares instead), or nothing.
std::optional<std::string_view> chaotic_pile(std::string_view name);

/// Why the oracle gives no trajectory to compare with for `name`: outside its domain, or a
/// chaotic pile; nothing when it gives one.
std::optional<std::string_view> no_oracle_trajectory(std::string_view name);

/// The options of a reference solution: rtol = atol = 1e-12, and 1e-14 under pairwise
/// gravitation, where orbits accumulate the per-step tolerance over many steps.
OracleOptions reference_options(const Scene& scene);

/// An oracle solution used as a reference, with its own error estimate.
struct OracleReference {
  Trajectory trajectory;                  ///< at the options given
  Differences estimate;                   ///< the same scene at rtol and atol / 100 against it
  double relative_estimate = 0.0;         ///< the estimate's position and velocity, relative to the
                                          ///< largest |p|, |v| (at least 1): the larger
  double cpu_per_simulated_second = 0.0;  ///< s/s, of the solution at the options given
};

/// The oracle's solution of the shipped scene `name` at `times` [s]. Adds to `list` a row with
/// its error estimate and CPU time per simulated second (criterion: relative estimate ≤ 1e-9).
/// Returns nothing, with a reported row, for a declared scene or a chaotic pile; nothing, with a
/// failed row naming the error, for a scene that leaves the domain unexpectedly (at either
/// tolerance).
std::optional<OracleReference> oracle_reference(CheckList& list, const std::string& name,
                                                const Scene& scene, std::span<const double> times,
                                                const OracleOptions& options);

/// The oracle references of one run of the suite, each solved once: sections that compare with
/// the same scene at the same instants and options (accuracy, peers) share its solution.
class OracleReferences {
 public:
  /// oracle_reference's answer; a reference solved before for the same scene name, instants
  /// (which end at the scene's duration) and options is given again, its row added to `list`
  /// again, without solving.
  std::optional<OracleReference> find(CheckList& list, const std::string& name, const Scene& scene,
                                      std::span<const double> times, const OracleOptions& options);

 private:
  struct Entry {
    std::string name;
    std::vector<double> times;
    OracleOptions options;
    OracleReference reference;
  };
  std::vector<Entry> entries_;
};

/// The row of a peer or method that cannot run `name`: a failure, naming what it said.
void cannot_run(CheckList& list, const std::string& name, const std::string& who,
                const std::string& what);

}  // namespace gp::verification
