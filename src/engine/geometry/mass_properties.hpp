#pragma once
// Area, centroid and polar second moment of area of a shape: its mass properties per unit
// density (DD:ctrOfMass, DD:momentOfInertia).

#include "scene/shape.hpp"

namespace gp {

/// Geometry of a shape that, times a density ρ (kg/m²), gives its mass m = ρ·area and its moment
/// of inertia about its centroid I = ρ·polar_moment.
struct MassProperties {
  double area;          ///< m²
  Vec2 centroid;        ///< m, in the shape's (body) frame
  double polar_moment;  ///< m⁴, ∫ |p − centroid|² dA over the shape
};

/// Closed forms, for a circle of radius r: area π r², polar moment π r⁴ / 2. For a polygon: a
/// fan of triangles (o, vᵢ, vᵢ₊₁) from a vertex o, each with area Dᵢ / 2, Dᵢ = (vᵢ − o) × (vᵢ₊₁ −
/// o), centroid o + (vᵢ + vᵢ₊₁ − 2o) / 3 and polar moment about o Dᵢ (|a|² + a·b + |b|²) / 12 with
/// a = vᵢ − o, b = vᵢ₊₁ − o; summed, then moved to the centroid by the parallel axis theorem. For a
/// capsule of core length L and radius r: a 2r × L rectangle plus two half discs, area
/// 2rL + π r², polar moment 2rL (L² + 4r²) / 12 + π r⁴ / 2 + π r² L² / 4 + 4 r³ L / 3 (each half
/// disc moved twice by the parallel axis theorem: to its own centroid 4r / 3π off its flat side,
/// then out to the capsule's centre). A segment with radius 0 is a line: area 0 and polar moment
/// 0, so it cannot give a body mass; its centroid is its midpoint.
MassProperties mass_properties(const Shape& shape);

}  // namespace gp
