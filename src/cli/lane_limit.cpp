#include "cli/lane_limit.hpp"

#include <string>

#include "engine/lanes.hpp"
#include "scene/input_error.hpp"

namespace gp::cli {

void limit_lanes(std::optional<int> lanes) {
  if (!lanes) return;
  const std::optional<Lanes> most = lanes_of(*lanes);
  if (!most) throw InputError("--lanes", "must be 1, 2 or 4", std::to_string(*lanes));
  gp::limit_lanes(*most);
}

}  // namespace gp::cli
