#pragma once
// The islands of a step's contacts: contacts joined through the dynamic bodies they share. Static
// and kinematic bodies do not join islands, as the solver never changes their motion.

#include <cstdint>
#include <vector>

#include "engine/core.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp {

/// Whether the solver's impulses change `body`'s motion (it has a finite mass or moment).
inline bool movable(const BodyInertia& m, BodyId body) {
  return m.inverse_mass[body] > 0.0 || m.inverse_moment[body] > 0.0;
}

/// The root of `body`'s tree in the union-find forest `parent` (per body: its parent, a root
/// its own), halving the path on the way so that the trees stay flat.
inline BodyId root_of(std::vector<BodyId>& parent, BodyId body) {
  while (parent[body] != body) body = parent[body] = parent[parent[body]];
  return body;
}

/// The contacts grouped by island, each island's in the contacts' own order. An island is named
/// by its root, its lowest body id; the arrays indexed by root are per body, and zero-sized
/// islands are those of bodies that are not roots.
struct ContactIslands {
  std::vector<BodyId> parent;  ///< per body: its island's root (after find)
  // 32-bit counts and indices: these arrays are per body and per contact.
  std::vector<std::uint32_t> points;        ///< per root: the island's number of points
  std::vector<std::uint32_t> order;         ///< contact indices, grouped by island
  std::vector<std::uint32_t> island_start;  ///< per root: its first entry in `order`
  std::vector<std::uint32_t> island_end;    ///< per root: one past its last entry in `order`
  std::vector<BodyId> roots;                ///< the roots of islands with contacts, ascending

  /// Groups `contacts` by island, reusing the arrays' room.
  void find(const ContactSet& contacts, const BodyInertia& inertia);
};

}  // namespace gp
