#include "engine/thread_count.hpp"

#include "scene/input_error.hpp"

namespace gp {

std::size_t thread_count(int threads, const std::string& field) {
  if (threads < 0) throw InputError(field, "must be >= 0 (0: every core)", std::to_string(threads));
  return static_cast<std::size_t>(threads);
}

}  // namespace gp
