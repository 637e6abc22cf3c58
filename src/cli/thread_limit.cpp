#include "cli/thread_limit.hpp"

#include "engine/thread_count.hpp"

namespace gp::cli {

void limit_threads(std::optional<tbb::global_control>& limit, int threads) {
  const std::size_t count = thread_count(threads, "--threads");
  if (count > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, count);
}

}  // namespace gp::cli
