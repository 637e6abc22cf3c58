#pragma once
// Numbers as the tables of figures print them (the bench summary, the speed section of the
// report): GCC 12 has no std::format.

#include <string>

namespace gp::bench {

/// `value` formatted by the printf `pattern` for one double, e.g. "%.2f"; at most 63 characters.
std::string formatted(const char* pattern, double value);

}  // namespace gp::bench
