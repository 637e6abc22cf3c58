#pragma once
// The --threads option of the commands that run on oneTBB's threads (simulate, ensemble).

#include <optional>

#include <tbb/global_control.h>

namespace gp::cli {

/// Limits oneTBB to `threads` threads while `limit` lives; 0 leaves every core. Throws an
/// InputError naming --threads for a negative count.
void limit_threads(std::optional<tbb::global_control>& limit, int threads);

}  // namespace gp::cli
