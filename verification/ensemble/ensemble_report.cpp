#include "verification/ensemble/ensemble_report.hpp"

#include "verification/suite/check.hpp"

namespace gp::verification {

void write_ensemble_report(std::ostream& md, const nlohmann::ordered_json& manifest,
                           const nlohmann::ordered_json& summary,
                           const std::vector<std::string>& plots) {
  md << "# Ensemble of " << manifest["scene"].get<std::string>() << "\n\n"
     << summary["samples"] << " samples (" << manifest["sampler"].get<std::string>() << ", seed "
     << manifest["seed"] << "), " << summary["failed"] << " failed; " << manifest["inputs"].size()
     << " perturbed inputs, each drawn uniformly within its relative "
     << "spread (ensemble.json). Data: samples.csv, energy.csv, summary.json.\n\n";
  for (const auto& error : summary["errors"]) md << "- " << error.get<std::string>() << "\n";
  md << "\n| column | mean | std | 5% | median | 95% |\n|---|---:|---:|---:|---:|---:|\n";
  for (const auto& [name, s] : summary["columns"].items()) {
    md << "| " << name << " | " << figure(s["mean"]) << " | " << figure(s["std"]) << " | "
       << figure(s["q05"]) << " | " << figure(s["q50"]) << " | " << figure(s["q95"]) << " |\n";
  }
  md << "\n";
  for (const std::string& plot : plots) md << "![" << plot << "](" << plot << ")\n";
}

}  // namespace gp::verification
