#pragma once
// The --lanes option of simulate: how wide the step's SIMD paths may run, to show that every
// width writes the same CSV.

#include <optional>

namespace gp::cli {

/// Narrows the SIMD paths to `lanes` doubles at a time (1, 2 or 4; the CPU's widest still bounds
/// them); none given leaves the widest. Throws an InputError naming --lanes for another count.
void limit_lanes(std::optional<int> lanes);

}  // namespace gp::cli
