#include "engine/scene/scene_space.hpp"

namespace gp {

std::unique_ptr<Space> build_space(const Scene& scene) {
  auto space = std::make_unique<Space>(scene.settings);
  for (const BodyDef& body : scene.bodies) space->add_body(body);
  return space;
}

}  // namespace gp
