#include "cli/thread_limit.hpp"

#include <string>

#include "scene/input_error.hpp"

namespace gp::cli {

void limit_threads(std::optional<tbb::global_control>& limit, int threads) {
  if (threads < 0) {
    throw InputError("--threads", "must be >= 0 (0: every core)", std::to_string(threads));
  }
  if (threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  }
}

}  // namespace gp::cli
