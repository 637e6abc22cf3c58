#pragma once
// A contact point that the oracle follows through time: a vertex of one body (the "first")
// touching an edge or a vertex of another (the "second"), each possibly rounded by a radius, and
// the contact's mode of friction. Its gap and slip are exact functions of the two bodies'
// motions (contact_kinematics.hpp), so that the constraint g = 0 can be held to round-off.

#include <cstddef>

#include "gamephysics/models/types.hpp"
#include "verification/oracle/geometry/contact_geometry.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// How the tangential force of a contact is found (Coulomb's law, in the plane).
enum class ContactMode {
  Frictionless,  ///< μ = 0: no tangential force
  Sticking,      ///< no slip: the tangential force is what holds it, |f_t| ≤ μ f_n
  Sliding,       ///< slipping with sign `slip_sign`: f_t = −μ f_n · slip_sign
};

/// Two hulls on different bodies, one of them dynamic, that may touch.
struct HullPair {
  std::size_t body_a;
  std::size_t hull_a;
  std::size_t body_b;
  std::size_t hull_b;
  double margin;  ///< m: how far one may move into the other between two looks for contact
};

struct ActiveContact {
  std::size_t pair;        ///< index of the watched pair of hulls it belongs to
  Feature feature;         ///< the features that touch, as the geometry named them for the pair
  std::size_t first;       ///< body owning the vertex
  std::size_t second;      ///< body owning the edge, or the other vertex
  std::size_t first_hull;  ///< the hull of the first body, and its vertex
  int first_vertex;
  std::size_t second_hull;  ///< the hull of the second body, and its edge or vertex
  int second_feature;
  Vec2 vertex;          ///< m: the first body's vertex, in its centre-of-mass frame
  bool on_edge;         ///< an edge of the second body; else a vertex of it
  Vec2 anchor;          ///< m: the edge's start, or the vertex, in the second's CoM frame
  Vec2 edge_end;        ///< m: the edge's end (on_edge), second's CoM frame
  Vec2 edge_normal;     ///< outward unit normal of the edge (on_edge), second's CoM frame
  double first_radius;  ///< m: rounding of the first's shape; the contact point is this far
                        ///< from the vertex, against the normal
  double radius;        ///< m: both roundings; the gap is the vertex's distance less this
  double friction;      ///< μ [1] of the two surfaces
  double restitution;   ///< C_R [1] of the two surfaces
  ContactMode mode = ContactMode::Frictionless;
  int slip_sign = 0;  ///< ±1 while Sliding: the sign of the slip along the tangent
};

/// The contact of `feature` between the hulls of `pair` (index `pair_index`) of `world`, in the
/// body frames, with the surfaces' combined friction μ = √(μ_a μ_b) and restitution
/// C_R = max(C_R,a, C_R,b) (docs/scene-format.md), its mode not yet chosen.
ActiveContact make_active_contact(const World& world, const HullPair& pair, std::size_t pair_index,
                                  const Feature& feature);

/// True when the two name the same features of the same pair.
bool same_contact(const ActiveContact& a, const ActiveContact& b);

}  // namespace gp::oracle
