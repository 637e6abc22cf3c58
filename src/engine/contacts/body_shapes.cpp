#include "engine/contacts/body_shapes.hpp"

#include <variant>

#include "engine/geometry/transform.hpp"

namespace gp {

void BodyShapes::add(ShapeRecord record) {
  while (first_.size() <= record.body) first_.push_back(static_cast<std::uint32_t>(size()));
  if (const auto* polygon = std::get_if<ConvexPolygon>(&record.local.geometry())) {
    polygon_vertices_ += static_cast<std::size_t>(polygon->count);
  }
  records_.push_back(std::move(record));
}

BodyShapes::Range BodyShapes::of_body(BodyId body) const {
  const auto end = static_cast<std::uint32_t>(size());
  const std::uint32_t first = body < first_.size() ? first_[body] : end;
  const std::uint32_t last = body + 1 < first_.size() ? first_[body + 1] : end;
  return {first, last};
}

void BodyShapes::place(const MotionState& s, WorldShapes& world) const {
  const bool first = world.size() != records_.size();
  if (first) world.lay_out(records_.size(), polygon_vertices_);
  for (std::size_t i = 0; i < records_.size(); ++i) {
    const ShapeRecord& r = records_[i];
    if (!r.moves && !first) continue;
    world.place(i, r.local, Transform(s.position[r.body], s.angle[r.body]));
  }
}

}  // namespace gp
