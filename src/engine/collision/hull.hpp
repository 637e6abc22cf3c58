#pragma once
// Polygons and segments seen alike: a segment is a two-vertex polygon with a radius, so that one
// separating-axis routine serves polygons, capsules and lines in the narrowphase and the signed
// distance. Internal to collision/.

#include <array>
#include <span>
#include <variant>

#include "engine/lanes.hpp"
#include "scene/shape.hpp"

namespace gp {

/// A convex outline (counter-clockwise vertices with outward edge normals, m) inflated by
/// `radius` (m). Views the storage it was made from.
struct Hull {
  std::span<const Vec2> vertices;
  std::span<const Vec2> normals;
  double radius;

  int count() const { return static_cast<int>(vertices.size()); }
  int next(int index) const { return index + 1 == count() ? 0 : index + 1; }
};

Hull hull_of(const PolygonView& polygon);

/// A segment as the two edges a→b and b→a; holds the storage its Hull views.
class SegmentOutline {
 public:
  explicit SegmentOutline(const Segment& segment);
  Hull hull() const { return {vertices_, normals_, radius_}; }

 private:
  std::array<Vec2, 2> vertices_;
  std::array<Vec2, 2> normals_;
  double radius_;
};

/// Calls `visit` with a polygon's or a segment's geometry (not a circle's) seen as a Hull, which
/// lives only for the call.
template <typename Visit>
auto visit_as_hull(const GeometryView& geometry, Visit&& visit) {
  if (const auto* polygon = std::get_if<PolygonView>(&geometry)) return visit(hull_of(*polygon));
  const SegmentOutline outline(*std::get_if<Segment>(&geometry));
  return visit(outline.hull());
}

/// The edge of `reference` along whose normal `other` is farthest out, and that distance (m):
/// max over edges i of min over vertices v of `other` of nᵢ·(v − vᵢ). Radii are not counted.
struct EdgeSeparation {
  int edge;
  double separation;
};

EdgeSeparation max_separation(const Hull& reference, const Hull& other);

/// How `lanes` takes a box's edges, for --explain: "its edges four at a time (AVX2)".
const char* box_lanes_name(Lanes lanes);

/// max_separation of a box against a box, `lanes` edges at a time (kFour only where
/// widest_lanes() is kFour, kTwo only where it is not kOne). Each gives the same edge and
/// separation to the bit; max_separation takes the widest.
EdgeSeparation max_separation_of_boxes(std::span<const Vec2, 4> vertices,
                                       std::span<const Vec2, 4> normals,
                                       std::span<const Vec2, 4> other, Lanes lanes);

/// The edge of `hull` whose normal is most nearly opposite `normal`: the edge that meets the
/// reference edge with that normal.
int incident_edge(const Hull& hull, const Vec2& normal);

}  // namespace gp
