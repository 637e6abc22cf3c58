#pragma once
// Renders traceability/ as Markdown and CSV: the SRS's four matrices, item -> function -> tests,
// and the edge differences between the SRS and the code. Output is byte-for-byte reproducible.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "verification/traceability/traceability.hpp"

namespace gp::verification {

/// File name (relative to traceability/) -> content.
using TraceFiles = std::map<std::string, std::string>;

TraceFiles render_traceability(const TraceInputs& inputs, const TraceResult& result);

/// Writes every file into `directory`, creating it, and removes nothing else.
void write_traceability(const TraceFiles& files, const std::filesystem::path& directory);

/// The files of `files` that are missing from `directory` or differ from it.
std::vector<std::string> stale_traceability(const TraceFiles& files,
                                            const std::filesystem::path& directory);

}  // namespace gp::verification
