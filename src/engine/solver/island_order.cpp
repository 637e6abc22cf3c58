#include "engine/solver/island_order.hpp"

#include <algorithm>

namespace gp {

void IslandOrderScratch::release() {
  // Moved-from temporaries take the room with them; `= {}` would keep a vector's capacity.
  ends = std::vector<End>();
  sides = std::vector<ItemEnds>();
  Eigen::SparseMatrix<double>().swap(neighbours);
  order.resize(0);
}

namespace {

// The neighbours of each of the island's `count` contacts into scratch.neighbours: column k holds
// the contacts from k on that share a movable body with contact k, k itself included.
void find_neighbours(std::uint32_t count, IslandOrderScratch& scratch) {
  const auto contact_of = [](const IslandOrderScratch::End& e) { return e.contact; };
  // Each pair of contacts on a body is entered once, in the lower triangle.
  const std::size_t entries = find_item_ends(scratch.ends, count, contact_of, scratch.sides);
  Eigen::SparseMatrix<double>& neighbours = scratch.neighbours;
  neighbours.resize(count, count);
  neighbours.reserve(static_cast<Eigen::Index>(entries / 2 + count));
  for (std::uint32_t k = 0; k < count; ++k) {
    neighbours.startVec(k);
    for_each_coupled(scratch.ends, scratch.sides[k], contact_of,
                     [&](std::uint32_t row, std::uint32_t, std::uint32_t) {
                       if (row >= k) neighbours.insertBack(row, k) = 1.0;
                     });
  }
  neighbours.finalize();
}

}  // namespace

void island_contacts_in_order(const ContactSet& contacts, const ContactIslands& islands,
                              std::size_t root, const BodyInertia& inertia,
                              IslandOrderScratch& scratch, std::vector<std::uint32_t>& ordered) {
  using End = IslandOrderScratch::End;
  const std::uint32_t first = islands.island_start[root];
  const std::uint32_t count = islands.island_end[root] - first;
  scratch.ends.clear();
  for (std::uint32_t k = 0; k < count; ++k) {
    const Contact& c = contacts[islands.order[first + k]];
    if (movable(inertia, c.body_a)) scratch.ends.push_back({c.body_a, k});
    if (movable(inertia, c.body_b)) scratch.ends.push_back({c.body_b, k});
  }
  std::sort(scratch.ends.begin(), scratch.ends.end(), [](const End& e, const End& f) {
    return e.body != f.body ? e.body < f.body : e.contact < f.contact;
  });
  find_neighbours(count, scratch);
  scratch.ordering(scratch.neighbours.selfadjointView<Eigen::Lower>(), scratch.order);
  ordered.clear();
  const int* const contact_at = scratch.order.indices().data();
  for (std::uint32_t q = 0; q < count; ++q) {
    ordered.push_back(islands.order[first + static_cast<std::uint32_t>(contact_at[q])]);
  }
}

}  // namespace gp
