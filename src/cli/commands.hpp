#pragma once
// The subcommands of build/bin/gamephysics. Each returns the process exit code:
// 0 success, 1 a check failed, 2 bad input.

#include <filesystem>

namespace gp::cli {

/// `gamephysics verify`: the main job. For now the SRS audit (catalogue, functions, tests,
/// dimensional checks, errata, edges, traceability/ up to date).
int verify(const std::filesystem::path& root);

/// `gamephysics trace`: writes the traceability files into `out`; with `check_only`, writes
/// nothing and fails when the copy in `out` is stale. Either way fails when a traceability check
/// fails.
int trace(const std::filesystem::path& root, const std::filesystem::path& out, bool check_only);

}  // namespace gp::cli
