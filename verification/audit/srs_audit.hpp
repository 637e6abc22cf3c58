#pragma once
// The SRS audit that `gamephysics verify` prints: catalogue, functions, tests, dimensional checks,
// errata and edges, with every failed check listed.

#include <filesystem>
#include <string>
#include <vector>

#include "verification/traceability/trace_report.hpp"

namespace gp::verification {

struct SrsAudit {
  TraceInputs inputs;
  TraceResult result;
  std::vector<std::string> stale;  ///< files of traceability/ that differ from a fresh render

  bool passed() const { return result.problems.empty() && stale.empty(); }
};

/// Runs the traceability checks on the tree at `root` and compares traceability/ with a fresh
/// render.
SrsAudit run_srs_audit(const std::filesystem::path& root);

/// The summary table, then one line per problem.
std::string format_srs_audit(const SrsAudit& audit);

}  // namespace gp::verification
