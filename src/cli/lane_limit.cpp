#include "cli/lane_limit.hpp"

#include <string>

#include "engine/lanes.hpp"
#include "scene/input_error.hpp"

namespace gp::cli {

void limit_lanes(std::optional<int> lanes) {
  if (!lanes) return;
  switch (*lanes) {
    case 1:
      gp::limit_lanes(Lanes::kOne);
      return;
    case 2:
      gp::limit_lanes(Lanes::kTwo);
      return;
    case 4:
      gp::limit_lanes(Lanes::kFour);
      return;
    default:
      throw InputError("--lanes", "must be 1, 2 or 4", std::to_string(*lanes));
  }
}

}  // namespace gp::cli
