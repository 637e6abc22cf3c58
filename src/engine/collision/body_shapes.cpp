#include "engine/collision/body_shapes.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <variant>

#include "engine/capacity.hpp"
#include "engine/collision/float_rounding.hpp"
#include "engine/geometry/shape_extent.hpp"
#include "engine/geometry/transform.hpp"

namespace gp {

void BodyShapes::add(BodyId body, const Shape& local, double restitution, double friction,
                     bool moves) {
  if (size() == kMaxShapes) {
    throw std::length_error("BodyShapes::add: more than 2^24 (16777216) shapes in a space");
  }
  while (first_.size() <= body) append(first_, static_cast<std::uint32_t>(size()));
  GeometryView kept = view_of(local.geometry());
  if (const auto* polygon = std::get_if<PolygonView>(&kept)) {
    const std::size_t count = polygon->vertices.size();
    // A pile of identical boxes keeps one block: a polygon the same as the last one added, bit
    // for bit, shares its block.
    const auto same = [count](std::span<const Vec2> a, std::span<const Vec2> b) {
      return a.size() == count && std::memcmp(a.data(), b.data(), count * sizeof(Vec2)) == 0;
    };
    if (same(last_polygon_.vertices, polygon->vertices) &&
        same(last_polygon_.normals, polygon->normals)) {
      polygons_.push_back(polygons_.back());
    } else {
      auto block = std::make_shared<Vec2[]>(2 * count);
      std::copy(polygon->vertices.begin(), polygon->vertices.end(), block.get());
      std::copy(polygon->normals.begin(), polygon->normals.end(), block.get() + count);
      polygons_.push_back(std::move(block));
    }
    const Vec2* block = polygons_.back().get();
    kept = last_polygon_ = PolygonView{std::span(block, count), std::span(block + count, count)};
    polygon_vertices_ += count;
  }
  const PackedGeometry packed(kept);
  append(records_, {packed, body, moves, float_above(core_reach(packed)), restitution, friction});
  if (restitution > 0.0) ++bouncing_;
  const double shape_reach = gp::reach(packed);
  reach_ = std::max(reach_, shape_reach);
  if (moves) moving_reach_ = std::max(moving_reach_, shape_reach);
  if (records_.back().offset_disc()) ++offset_discs_;
}

BodyShapes::Range BodyShapes::of_body(BodyId body) const {
  const auto end = static_cast<std::uint32_t>(size());
  const std::uint32_t first = body < first_.size() ? first_[body] : end;
  const std::uint32_t last = body + 1 < first_.size() ? first_[body + 1] : end;
  return {first, last};
}

BodyShapes::Range BodyShapes::remove_body(BodyId body) {
  const Range removed = of_body(body);
  // The polygons' blocks are in the order of their shapes.
  const auto is_polygon = [](const ShapeRecord& r) {
    return r.local.kind() == ShapeKind::kPolygon;
  };
  const auto before = records_.begin() + removed.first;
  const auto after = records_.begin() + removed.last;
  const auto first_block = std::count_if(records_.begin(), before, is_polygon);
  const auto blocks = std::count_if(before, after, is_polygon);
  for (auto r = before; r != after; ++r) {
    if (is_polygon(*r)) polygon_vertices_ -= r->local.polygon().vertices.size();
    if (r->restitution > 0.0) --bouncing_;
    if (r->offset_disc()) --offset_discs_;
  }
  polygons_.erase(polygons_.begin() + first_block, polygons_.begin() + first_block + blocks);
  last_polygon_ = {};  // its block may have gone with the body
  records_.erase(before, after);
  const std::uint32_t count = removed.last - removed.first;
  for (std::size_t b = body + std::size_t{1}; b < first_.size(); ++b) first_[b] -= count;
  return removed;
}

}  // namespace gp
