#pragma once
// Signed distance, normal and contact points between two placed hulls, for every pair of shape
// kinds (disc, polygon, capsule, bare segment), written for clarity: every vertex–edge and
// vertex–vertex pair is enumerated.

#include <vector>

#include "verification/oracle/geometry/feature.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

struct ContactPoint {
  Vec2 point;         ///< m, world: midway between the two surfaces at `feature`
  double separation;  ///< m: the feature pair's gap (feature_gap); negative when overlapping
  Feature feature;
};

struct ContactGeometry {
  double distance;  ///< m: signed distance between the hulls (signed_distance)
  Vec2 normal;      ///< unit, from B towards A: the normal of the deepest (or closest) feature pair
  /// None when the hulls are farther apart than the margin, or both are bare segments (lines have
  /// no area and never touch); else 1, or 2 when an edge lies along the other hull's reference
  /// edge within the margin (its ends clipped to that edge, as for a face contact).
  std::vector<ContactPoint> points;
};

/// Signed distance [m] between `a` at `pa` and `b` at `pb`: the gap between the surfaces when the
/// cores are apart (the least distance between a vertex of one and a vertex or edge of the other,
/// minus both radii); when the cores overlap, minus their penetration depth (the largest
/// separation along any edge normal of either, as the separating axis theorem measures it) minus
/// both radii. Continuous in the poses, negative when the hulls overlap.
double signed_distance(const Hull& a, const Pose& pa, const Hull& b, const Pose& pb);

/// The contact between `a` and `b`: distance and normal as above, and the points whose feature
/// pairs are apart by at most `margin` [m, ≥ 0]. The reference edge is the one whose feature pair
/// sets the distance; the incident edge is the other hull's edge most nearly opposite it. Its
/// ends inside the reference edge's side planes are vertex–edge points against the reference
/// edge; where a side plane cuts it, the reference edge's end is a vertex–edge point against the
/// incident edge, unless its foot on that edge's line falls off the edge while the reference end
/// is outside the incident core (steep edges), where the vertex–edge gap would measure to a line
/// the hull does not reach; inside the core (a deep overlap) the line measures its depth.
ContactGeometry contact_geometry(const Hull& a, const Pose& pa, const Hull& b, const Pose& pb,
                                 double margin);

}  // namespace gp::oracle
