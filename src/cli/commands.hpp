#pragma once
// The subcommands of build/bin/gamephysics. Each returns the process exit code:
// 0 success, 1 a check failed, 2 bad input.

#include <filesystem>

namespace gp::cli {

/// `gamephysics verify`: the main job. For now the SRS audit (catalogue, functions, tests,
/// dimensional checks, errata, edges, traceability/ up to date).
int verify(const std::filesystem::path& root);

/// `gamephysics trace`: writes traceability/ under `root`; with `check_only`, writes nothing and
/// fails when the committed copy is stale or a traceability check fails.
int trace(const std::filesystem::path& root, bool check_only);

}  // namespace gp::cli
