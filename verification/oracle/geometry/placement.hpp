#pragma once
// A hull placed in the world by its body's pose, and the outward normals of its edges.

#include <span>
#include <vector>

#include "gamephysics/models/types.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// World vertices [m] of `hull` at `pose`: p + R(ϕ) v for each vertex v.
std::vector<Vec2> placed_vertices(const Hull& hull, const Pose& pose);

/// Outward unit normal of edge i (from vertex i to i+1 mod n) of a hull with n ≥ 2 vertices, in the
/// frame of `vertices`: the edge direction turned clockwise, which points out of a
/// counter-clockwise polygon. For n = 2 the two edges are the segment's two sides (normals
/// opposite).
Vec2 edge_normal(std::span<const Vec2> vertices, int edge);

/// m: the farthest point of `hull` from its body's centre of mass (the origin of its frame).
double reach(const Hull& hull);

/// How many edges a hull of `vertex_count` vertices has: none for a disc, the two sides of a
/// segment, one per vertex of a polygon.
inline int edge_count(int vertex_count) {
  return vertex_count == 1 ? 0 : vertex_count;
}

}  // namespace gp::oracle
