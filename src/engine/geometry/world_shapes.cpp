#include "engine/geometry/world_shapes.hpp"

#include <stdexcept>

namespace gp {

void WorldShapes::lay_out(std::size_t count, std::size_t polygon_vertices) {
  shapes_.assign(count, WorldShapeView{});
  pool_.clear();
  // The pool never grows past this, so that the views into it stay valid.
  pool_.reserve(2 * polygon_vertices);
}

void WorldShapes::place(std::size_t i, const GeometryView& local, const Transform& transform) {
  const auto* polygon = std::get_if<PolygonView>(&local);
  if (polygon == nullptr) {
    // A disc or a segment is copied into its view: nothing refers to the temporary.
    shapes_[i] = WorldShapeView(to_world(local, transform));
    return;
  }
  const std::size_t count = polygon->vertices.size();
  Vec2* room = nullptr;
  if (const auto* placed = std::get_if<PolygonView>(&shapes_[i].geometry)) {
    // The room it was first given, reached through the pool: its view only reads.
    room = pool_.data() + (placed->vertices.data() - pool_.data());
  } else {
    if (pool_.size() + 2 * count > pool_.capacity()) {
      throw std::logic_error("WorldShapes::place: more polygon vertices than laid out");
    }
    pool_.resize(pool_.size() + 2 * count);
    room = pool_.data() + pool_.size() - 2 * count;
  }
  const std::span<Vec2> vertices(room, count);
  const std::span<Vec2> normals(room + count, count);
  shapes_[i] = {PolygonView{vertices, normals},
                place_polygon(*polygon, transform, vertices, normals)};
}

}  // namespace gp
