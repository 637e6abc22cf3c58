#pragma once
// The section "speed against the peers" in the report: Markdown, HTML and speed.json.

#include <string>

#include "verification/suite/speed_table.hpp"

namespace gp::verification {

/// The section in Markdown (with its heading), or why it is missing.
std::string speed_markdown(const SpeedSection& section);

/// The section in HTML (with its heading), or why it is missing.
std::string speed_html(const SpeedSection& section);

/// The table as JSON: how it was measured, the engines' settings, the targets and, per workload
/// and engine, the figures of bench::Figures with ours/engine.
std::string speed_json(const SpeedTable& table);

}  // namespace gp::verification
