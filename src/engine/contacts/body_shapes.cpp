#include "engine/contacts/body_shapes.hpp"

#include "engine/geometry/transform.hpp"

namespace gp {

void BodyShapes::place(const MotionState& s, std::vector<WorldShape>& world) const {
  const bool first = world.size() != records_.size();
  if (first) world.resize(records_.size());
  for (std::size_t i = 0; i < records_.size(); ++i) {
    const ShapeRecord& r = records_[i];
    if (!r.moves && !first) continue;
    world[i] = to_world(r.local, Transform(s.position[r.body], s.angle[r.body]));
  }
}

}  // namespace gp
