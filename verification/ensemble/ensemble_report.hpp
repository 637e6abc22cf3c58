#pragma once
// report.md of an ensemble: what was run, the spread of every output and the plots.

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace gp::verification {

/// Writes the report of the ensemble described by `manifest` (ensemble.json) with its `summary`
/// (summarize_samples) and the `plots` (PNG names beside it).
void write_ensemble_report(std::ostream& md, const nlohmann::ordered_json& manifest,
                           const nlohmann::ordered_json& summary,
                           const std::vector<std::string>& plots);

}  // namespace gp::verification
