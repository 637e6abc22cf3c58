#pragma once
// The order in which a large island's points enter its sparse solve, one whose Cholesky factor
// stays sparse (a pile's points, numbered as its contacts come, would fill it in). Chosen over the
// island's contacts rather than its points: a contact's points share their neighbours, and the
// graph of contacts is a third the size. K is then assembled in that order, not permuted after.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include "engine/solver/contact_islands.hpp"
#include "engine/solver/coupled_items.hpp"

namespace gp {

/// The room of island_contacts_in_order, kept from one island to the next.
struct IslandOrderScratch {
  // A contact's end on one of its movable bodies; `contact` is its place in the island.
  struct End {
    BodyId body;
    std::uint32_t contact;
  };
  std::vector<End> ends;        // by body, then contact
  std::vector<ItemEnds> sides;  // per contact: its ends, by body
  // Two contacts are neighbours where they share a movable body: the lower triangle and the
  // diagonal of that graph, which AMD asks for.
  Eigen::SparseMatrix<double> neighbours;
  Eigen::AMDOrdering<int> ordering;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;

  /// Frees the room a large island took.
  void release();
};

/// The contacts of the island of `root` in an order whose factor stays sparse (AMD over the
/// contacts, two sharing a movable body of `inertia` being neighbours), into `ordered` as indices
/// into `contacts`.
void island_contacts_in_order(const ContactSet& contacts, const ContactIslands& islands,
                              std::size_t root, const BodyInertia& inertia,
                              IslandOrderScratch& scratch, std::vector<std::uint32_t>& ordered);

}  // namespace gp
