#pragma once
// The pair of features, one on each hull, that a contact point comes from, and the gap between
// them: a function of the two bodies' poses that a root finder can follow as they move.

#include <span>

#include "gamephysics/models/types.hpp"

namespace gp::oracle {

/// Which features of A and B make a contact point (V: placed vertices, N: outward edge normals,
/// r: radii):
///  VertexEdge:   gap = (V_A[a] − V_B[b])·N_B[b] − r_A − r_B, normal = N_B[b] (edge b of B)
///  EdgeVertex:   gap = (V_B[b] − V_A[a])·N_A[a] − r_A − r_B, normal = −N_A[a] (edge a of A)
///  VertexVertex: gap = |V_A[a] − V_B[b]| − r_A − r_B, normal = (V_A[a] − V_B[b]) / |…|
/// The normal points from B towards A.
struct Feature {
  enum class Kind { VertexEdge, EdgeVertex, VertexVertex };
  Kind kind;
  int a;
  int b;
  bool operator==(const Feature&) const = default;
};

/// A hull placed in the world: its vertices [m] and its radius [m].
struct PlacedHull {
  std::span<const Vec2> vertices;
  double radius;
};

/// The feature pair's gap [m], by the formula of its kind.
double feature_gap(const Feature& feature, const PlacedHull& a, const PlacedHull& b);

/// The feature pair's unit normal, from B towards A; (0, 1) for two coincident vertices, which
/// have no direction of their own.
Vec2 feature_normal(const Feature& feature, const PlacedHull& a, const PlacedHull& b);

/// The point [m] midway between the two surfaces at the feature pair: the vertex's surface point
/// and the other feature's, both along the feature's normal.
Vec2 feature_point(const Feature& feature, const PlacedHull& a, const PlacedHull& b);

}  // namespace gp::oracle
