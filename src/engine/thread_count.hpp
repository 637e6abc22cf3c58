#pragma once
// The number of threads a user asks the engine to run on, checked once for the command line and
// Python alike.

#include <cstddef>
#include <string>

namespace gp {

/// `threads` as a user asked for it in `field` (the command line's --threads, Python's
/// set_threads): that many threads, 0 for every core. Throws an InputError naming `field` when it
/// is negative.
std::size_t thread_count(int threads, const std::string& field);

}  // namespace gp
