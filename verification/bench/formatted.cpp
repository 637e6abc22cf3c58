#include "verification/bench/formatted.hpp"

#include <cstdio>

namespace gp::bench {

std::string formatted(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace gp::bench
