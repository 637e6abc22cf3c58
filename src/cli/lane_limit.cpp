#include "cli/lane_limit.hpp"

#include "engine/lanes.hpp"

namespace gp::cli {

void limit_lanes(std::optional<int> lanes) {
  if (!lanes) return;
  gp::limit_lanes(lanes_of(*lanes, "--lanes"));
}

}  // namespace gp::cli
