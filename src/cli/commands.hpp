#pragma once
// The subcommands of build/bin/gamephysics. Each returns the process exit code:
// 0 success, 1 a check failed, 2 bad input.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace gp::cli {

/// Exit codes: a run or a check failed; the input was bad. 0 is success.
inline constexpr int kRunFailed = 1;
inline constexpr int kBadInput = 2;

struct VerifyOptions {
  std::filesystem::path root;  ///< the repository: srs/, scenes/, tests/, traceability/
  std::filesystem::path out;   ///< the report folder
  bool quick = false;          ///< short runs only (what ctest runs)
  /// The JUnit report of a run of the Catch2 tests, whose results the audit page shows.
  std::optional<std::filesystem::path> test_results;
  bool long_runs = false;     ///< the rain and pyramid for 1e6 steps each (hours)
  int speed_repetitions = 3;  ///< runs per workload and engine in the speed section
};

/// `gamephysics verify`: the main job. The SRS audit (catalogue, functions, tests, dimensional
/// checks, errata, edges, traceability/ up to date), then the verification suite against the
/// SUNDIALS oracle; writes the report into `out`.
int verify(const VerifyOptions& options);

/// `gamephysics trace`: writes the traceability files into `out`; with `check_only`, writes
/// nothing and fails when the copy in `out` is stale. Either way fails when a traceability check
/// fails.
int trace(const std::filesystem::path& root, const std::filesystem::path& out, bool check_only);

struct SimulateOptions {
  std::filesystem::path scene;
  std::optional<std::filesystem::path> out;  ///< the trajectory CSV to write
  SceneOverrides overrides;
  bool explain = false;  ///< print the pipeline of a step
  /// The step's contact passes and narrowphase run on this many threads (0: every core), with
  /// the same result to the bit on any number. One by default: verification runs many
  /// simulations side by side, and a run's time should not depend on the machine's cores.
  int threads = 1;
  /// The step's SIMD paths take at most this many doubles at a time (1, 2 or 4), with the same
  /// result to the bit on any; none: the widest the CPU has.
  std::optional<int> lanes;
};

/// `gamephysics simulate`: runs a scene file and writes its trajectory as CSV; with `explain`,
/// prints the pipeline of a step first (and runs nothing without `out`). Exits 2 for bad input and
/// 1 when the run fails (a non-finite state), writing no file either way.
int simulate(const SimulateOptions& options);

struct OracleCommandOptions {
  std::filesystem::path scene;
  std::filesystem::path out;                    ///< the trajectory CSV to write
  std::optional<std::filesystem::path> events;  ///< the impact log CSV to write
  SceneOverrides overrides;                     ///< duration and output_dt; dt is not used
  std::string method = "cvode-adams";  ///< cvode-adams, cvode-bdf, arkode-erk or time-stepping
  std::optional<double> rtol;          ///< default: the oracle's
  std::optional<double> atol;
  std::optional<double> step;  ///< s: time-stepping's step; default: the oracle's
};

/// `gamephysics oracle`: integrates a scene file with the SUNDIALS oracle (verification/oracle)
/// and writes its trajectory as the CSV of `simulate`, and its impacts. Exits 2 for bad input or a
/// scene outside the oracle's domain and 1 when the output cannot be written, writing no file
/// either way.
int oracle(const OracleCommandOptions& options);

struct PeerOptions {
  std::filesystem::path scene;
  std::filesystem::path out;       ///< the trajectory CSV to write
  std::string engine;              ///< one of peers::engine_choices()
  std::string config = "matched";  ///< default (as its users run it) or matched (to ours)
  SceneOverrides overrides;
};

/// `gamephysics peer`: a scene file run by Chipmunk2D or Box2D (verification/peers), written as
/// the CSV of `simulate`.
int peer(const PeerOptions& options);

struct ViewOptions {
  std::filesystem::path scene;
  std::filesystem::path out;  ///< the HTML page to write
  SceneOverrides overrides;
  bool oracle = false;  ///< overlay the SUNDIALS oracle's solution
  /// The audit page (`gamephysics audit`), as the page links to it: each SRS id then links to
  /// its entry there. Empty: no links.
  std::string audit;
};

/// `gamephysics view`: runs a scene file as `simulate` does and writes one self-contained HTML
/// page that plays the run back with its energies, momenta, contacts and impacts; with `oracle`,
/// over the oracle's solution. Exits 2 for bad input (or a scene outside the oracle's domain with
/// `oracle`) and 1 when the run fails, writing no file either way.
int view(const ViewOptions& options);

/// `gamephysics audit`: the SRS audit alone, printed and written as `out`/audit.html (the audit
/// page of `verify`, without the suite's checks), with the results in `test_results` (a JUnit
/// report of the Catch2 tests) if given. Exits 1 when a traceability check fails.
int audit(const std::filesystem::path& root, const std::filesystem::path& out,
          const std::optional<std::filesystem::path>& test_results);
struct LongRunOptions {
  std::filesystem::path scene;
  long steps = 1000000;
  std::optional<std::size_t> bodies;  ///< keep only the first this many bodies of the file
};

/// `gamephysics longrun`: steps a scene file `steps` times by its dt and checks that every state
/// stays finite, that no body leaves the box it starts in and that the resident memory does not
/// grow; prints the figures. Exits 0 when all hold, 1 when one fails, 2 for bad input.
int longrun(const LongRunOptions& options);

/// `gamephysics bench`: runs build/bin/gamephysics_bench (ours, Chipmunk2D, Box2D).
int bench(bool quick);

struct EnsembleOptions {
  std::filesystem::path scene;
  SceneOverrides overrides;
  std::uint64_t samples = 0;
  std::string uncertainty = "srs";  ///< "srs" or an uncertainty file (docs/ensembles.md)
  std::string sampler = "sobol";    ///< sobol or random
  std::uint64_t seed = 0;
  std::filesystem::path out;  ///< the ensemble's folder
  bool resume = false;        ///< keep the completed chunks in `out`, run the rest
  int threads = 0;            ///< per process; 0: every core
  bool oracle = false;        ///< run each sample in the oracle too, and compare
  bool no_plots = false;
  /// Instead of the ensemble: each integrator's numerical error against the input spread.
  bool compare_numerical_error = false;
};

/// `gamephysics ensemble`: runs `samples` perturbed copies of a scene (docs/ensembles.md) on every
/// core and, under an MPI launcher, on every rank; writes samples.csv, energy.csv, summary.json,
/// report.md and plots into `out`. Exits 2 for bad input (writing nothing), 1 when the output
/// cannot be written; failed samples are recorded, not fatal. With compare_numerical_error,
/// writes instead numerical_error_vs_spread.csv and .md into `out`: per integrator, whether its
/// numerical error is below the input spread.
int ensemble(const EnsembleOptions& options);

}  // namespace gp::cli
