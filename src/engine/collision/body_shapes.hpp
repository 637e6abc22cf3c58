#pragma once
// Every shape of the space with its body and surface, and where each is in the world.

#include <cstdint>
#include <memory>
#include <span>
#include <variant>
#include <vector>

#include "engine/dynamics/force_model.hpp"
#include "engine/geometry/packed_geometry.hpp"
#include "engine/geometry/transform.hpp"
#include "engine/geometry/world_bounds.hpp"
#include "engine/geometry/world_shapes.hpp"
#include "engine/threads.hpp"
#include "scene/body.hpp"

namespace gp {

/// A shape of a body, in the body frame centred on the centre of mass; a polygon's vertices are
/// BodyShapes' to keep. 72 bytes: with the geometry as a GeometryView, whose variant and 16-byte
/// alignment take 64 bytes, it would take 96. `body`, `moves` and `core_reach` lie in the room that
/// `local`'s kind leaves at its end (no_unique_address), where a field of their own would take 8
/// bytes more a shape; nothing assigns `local` alone, which could write over them.
struct ShapeRecord {
  [[no_unique_address]] PackedGeometry local;
  BodyId body;
  bool moves;  ///< false for the shapes of static bodies
  /// m: core_reach of `local`, rounded up to a float: a turn of the body moves the shape's box by
  /// at most this much per radian.
  float core_reach;
  double restitution;
  double friction;

  /// Whether this is a disc about its body's centre of mass, which its body's turning leaves where
  /// it is.
  bool centred_disc() const {
    return local.kind() == ShapeKind::kCircle && local.circle().center == Vec2::Zero();
  }
  /// Whether this is a disc off its body's centre of mass.
  bool offset_disc() const { return local.kind() == ShapeKind::kCircle && !centred_disc(); }
  /// Where this shape is when its body's centre of mass is at `position`, turned by `angle`: a
  /// disc about the centre of mass is not turned, so that placing it needs no sine.
  Transform frame(const Vec2& position, double angle) const {
    return centred_disc() ? Transform(position) : Transform(position, angle);
  }
};
static_assert(sizeof(ShapeRecord) == 72, "ShapeRecord's fields after `local` fit in its tail");

/// The shapes of a space, and their world placement for a given motion state.
class BodyShapes {
 public:
  /// The most shapes a space holds: the warm starts number them in 24 bits (WarmStart::key).
  static constexpr std::size_t kMaxShapes = std::size_t{1} << 24;

  /// Adds shape `local` of `body` with its surface; shapes are added body by body, in increasing
  /// body order. Throws std::length_error, adding nothing, past kMaxShapes shapes.
  void add(BodyId body, const Shape& local, double restitution, double friction, bool moves);
  std::size_t size() const { return records_.size(); }
  const ShapeRecord& operator[](std::size_t i) const { return records_[i]; }
  /// Whether a shape has a coefficient of restitution above 0: without one, no contact bounces.
  bool any_bounce() const { return bouncing_ > 0; }
  /// The farthest any point of a moving shape (a dynamic or kinematic body's) lies from its
  /// body's centre of mass [m] (reach), over every shape added: removing a body leaves it, still
  /// a bound.
  double moving_reach() const { return moving_reach_; }
  /// The same over every shape, static ones included [m].
  double reach() const { return reach_; }
  /// Whether a disc lies off its body's centre of mass (AnchorKind::kOffsetDisc).
  bool any_offset_disc() const { return offset_discs_ > 0; }

  /// The indices [first, last) of the shapes of `body`.
  struct Range {
    std::uint32_t first;
    std::uint32_t last;
  };
  Range of_body(BodyId body) const;
  /// Removes the shapes of `body` and returns the indices they had: the shapes after them move
  /// down by as many, and `body` keeps an empty range.
  Range remove_body(BodyId body);

  /// The `unmoved` of place and bound_moved that leaves no body out.
  struct NoneUnmoved {
    bool operator()(BodyId) const { return false; }
  };

  /// Places every moving shape, whole in WorldShapes or its box alone in WorldBounds, by its
  /// body's centre of mass `position` and orientation `angle`, indexed by body id (static shapes
  /// once, on the first call). The shapes of a body for which `unmoved(body)` is true are left
  /// where the last call placed them (all are placed on the first call).
  template <typename Placements, typename Unmoved = NoneUnmoved>
  void place(std::span<const Vec2> position, std::span<const double> angle, Placements& world,
             const Unmoved& unmoved = {}) const;

  /// Bounds in `end` every moving shape at the end of a step of h [s] along `path`, from the
  /// centres of mass `from` [m, by body id] at which `start` placed the shapes: a disc about its
  /// centre of mass exactly where `path.position(body, h)` [m] puts it, as it needs no sine, every
  /// other shape by its box in `start` moved and grown for `path.turn(body, h)` [rad]
  /// (moved_bounds), which needs none either. (`Path`: Ballistic's interface.) The shapes of a
  /// body for which `unmoved(body)` is true keep the bounds of the last call, as in place.
  template <typename Path, typename Unmoved = NoneUnmoved>
  void bound_moved(const WorldShapes& start, std::span<const Vec2> from, const Path& path, double h,
                   WorldBounds& end, const Unmoved& unmoved = {}) const;

 private:
  void lay_out(WorldShapes& world) const {
    world.lay_out(records_.size(), polygons_.size(), polygon_vertices_);
  }
  void lay_out(WorldBounds& world) const { world.lay_out(records_.size()); }
  /// Calls `work(record, index)` for each shape that `world` must place: the moving ones but
  /// those of `unmoved` bodies, and every one at the first placement, which lays `world` out.
  template <typename Placements, typename Unmoved, typename Work>
  void each_to_place(Placements& world, const Unmoved& unmoved, const Work& work) const;

  std::vector<ShapeRecord> records_;
  // Per polygon, its vertices then its normals: a block, which stays where it is as shapes are
  // added, sized to the polygon rather than to kMaxPolygonVertices as a Shape is, and shared
  // with the polygons added after it that are the same.
  std::vector<std::shared_ptr<const Vec2[]>> polygons_;
  PolygonView last_polygon_;          // in the last polygon's block
  std::size_t polygon_vertices_ = 0;  // of all the polygons among the shapes
  std::size_t bouncing_ = 0;          // shapes with a restitution above 0
  double moving_reach_ = 0.0;
  double reach_ = 0.0;
  std::size_t offset_discs_ = 0;
  std::vector<std::uint32_t> first_;  // per body up to the last with shapes: its first shape
};

template <typename Placements, typename Unmoved, typename Work>
void BodyShapes::each_to_place(Placements& world, const Unmoved& unmoved, const Work& work) const {
  const bool first = world.size() != records_.size();
  if (first) lay_out(world);
  const auto to_place = [&](std::size_t i) {
    const ShapeRecord& r = records_[i];
    return (r.moves && !unmoved(r.body)) || first;
  };
  // On several threads a shape's room was last written by either core and read by both: its
  // lines are asked for a few shapes ahead of the stores (prefetch.hpp). On one, the asking
  // costs many_pyramids' step 3%.
  constexpr std::size_t kShapesAhead = 4;
  const bool ask_ahead = !first && !one_thread();
  const auto place_shapes = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t ahead = i + kShapesAhead;
      if (ask_ahead && ahead < end && to_place(ahead)) world.prefetch_for_placing(ahead);
      if (to_place(i)) work(records_[i], i);
    }
  };
  // Once placed, each shape has its own room in `world`: the shapes are placed side by side.
  constexpr std::size_t kShapesPerTask = 1024;  // a shape costs tens of nanoseconds
  for_blocks(records_.size(), kShapesPerTask, first, place_shapes);
}

template <typename Placements, typename Unmoved>
void BodyShapes::place(std::span<const Vec2> position, std::span<const double> angle,
                       Placements& world, const Unmoved& unmoved) const {
  each_to_place(world, unmoved, [&](const ShapeRecord& r, std::size_t i) {
    world.place(i, r.local, r.frame(position[r.body], angle[r.body]));
  });
}

template <typename Path, typename Unmoved>
void BodyShapes::bound_moved(const WorldShapes& start, std::span<const Vec2> from, const Path& path,
                             double h, WorldBounds& end, const Unmoved& unmoved) const {
  each_to_place(end, unmoved, [&](const ShapeRecord& r, std::size_t i) {
    const Vec2 to = path.position(r.body, h);
    if (r.centred_disc()) {
      end.place(i, r.local, Transform(to));
    } else {
      end.place(
          i, moved_bounds(start.bounds(i), to - from[r.body], path.turn(r.body, h), r.core_reach));
    }
  });
}

}  // namespace gp
