#include "engine/geometry/world_shapes.hpp"

#include <stdexcept>
#include <variant>

namespace gp {

void WorldShapes::lay_out(std::size_t count, std::size_t polygons, std::size_t polygon_vertices) {
  shapes_.assign(count, PackedGeometry{});
  pool_.clear();
  // The pool never grows past this, so that the views into it stay valid.
  pool_.reserve(2 * polygon_vertices + 2 * polygons);
}

void WorldShapes::place(std::size_t i, const GeometryView& local, const Transform& transform) {
  // Not through a PackedGeometry: a polygon's normals need not follow its vertices here.
  if (const auto* polygon = std::get_if<PolygonView>(&local)) {
    place_in_pool(i, *polygon, transform);
  } else {
    place(i, PackedGeometry(local), transform);
  }
}

void WorldShapes::place(std::size_t i, const PackedGeometry& local, const Transform& transform) {
  // A disc or a segment straight into its packed form: through to_world, it would be built as a
  // WorldShape, with room for a polygon, first.
  switch (local.kind()) {
    case ShapeKind::kCircle:
      shapes_[i] = PackedGeometry(moved(local.circle(), transform));
      return;
    case ShapeKind::kSegment:
      shapes_[i] = PackedGeometry(moved(local.segment(), transform));
      return;
    case ShapeKind::kPolygon:
      break;
  }
  place_in_pool(i, local.polygon(), transform);
}

void WorldShapes::place_in_pool(std::size_t i, const PolygonView& polygon,
                                const Transform& transform) {
  const std::size_t count = polygon.vertices.size();
  const std::size_t room_size = 2 * count + 2;
  Vec2* room = nullptr;
  if (shapes_[i].kind() == ShapeKind::kPolygon) {
    // The room it was first given, reached through the pool: its view only reads.
    const Vec2* placed = shapes_[i].polygon().vertices.data();
    room = pool_.data() + (placed - pool_.data());
  } else {
    if (pool_.size() + room_size > pool_.capacity()) {
      throw std::logic_error("WorldShapes::place: more polygon vertices than laid out");
    }
    pool_.resize(pool_.size() + room_size);
    room = pool_.data() + pool_.size() - room_size;
  }
  const std::span<Vec2> vertices(room, count);
  const std::span<Vec2> normals(room + count, count);
  const Aabb bounds = place_polygon(polygon, transform, vertices, normals);
  room[2 * count] = bounds.min;
  room[2 * count + 1] = bounds.max;
  shapes_[i] = PackedGeometry(PolygonView{vertices, normals});
}

}  // namespace gp
