#pragma once
// `gamephysics verify`, the main job: the SRS audit, then every scene of scenes/ against the
// SUNDIALS oracle with every game integrator, convergence orders, conservation over long runs,
// the hard cases and speed against error; a report with tables and plots.

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "verification/suite/check.hpp"
#include "verification/suite/oracle_domain.hpp"

namespace gp::verification {

struct SuiteOptions {
  std::filesystem::path root;        ///< the repository: scenes/, srs/, tests/, traceability/
  std::filesystem::path out;         ///< where the report goes (out/report)
  bool quick = false;                ///< short runs only: what ctest runs
  bool long_runs = false;            ///< the long runs at 1e6 steps (hours): `verify --long`
  int speed_repetitions = 3;         ///< runs per workload and engine in the speed section (≥ 1)
  std::ostream* progress = nullptr;  ///< a line per scene and stage
};

/// A scene of scenes/ with its file name without extension.
struct NamedScene {
  std::string name;
  Scene scene;
};

/// Every scene of `directory`, sorted by name.
std::vector<NamedScene> load_scenes(const std::filesystem::path& directory);

/// The sections of the suite; each returns its rows. `data` receives CSV files (name → text)
/// for the report's plots.
using CsvFiles = std::vector<std::pair<std::string, std::string>>;
std::vector<Check> accuracy_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                                   OracleReferences& references, CsvFiles& data);
std::vector<Check> convergence_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                                      CsvFiles& data);
std::vector<Check> closed_form_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o);
std::vector<Check> pile_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                               CsvFiles& data);
std::vector<Check> conservation_checks(const std::vector<NamedScene>& scenes,
                                       const SuiteOptions& o);
std::vector<Check> hard_case_checks(const SuiteOptions& o);
std::vector<Check> long_run_checks(const SuiteOptions& o);
std::vector<Check> stability_checks(const SuiteOptions& o);
std::vector<Check> peer_checks(const std::vector<NamedScene>& scenes, const SuiteOptions& o,
                               OracleReferences& references, CsvFiles& data);
std::vector<Check> work_precision_checks(const std::vector<NamedScene>& scenes,
                                         const SuiteOptions& o, CsvFiles& data);
/// The rows above held to the rule that a limit sits within kLooseness of its figure or says
/// why not (loose_rows): a failed row naming them in the full run; reported under o.quick, whose
/// shorter runs measure less than the full run the limits are set for.
std::vector<Check> criteria_level_checks(const std::vector<Check>& checks, const SuiteOptions& o);

struct SuiteResult {
  bool passed;                ///< every check passed
  std::vector<Check> checks;  ///< the audit rows, then every check of the suite
};

/// Runs everything, writes the report, prints the summary.
SuiteResult run_suite(const SuiteOptions& options, const std::vector<Check>& audit_rows);

}  // namespace gp::verification
