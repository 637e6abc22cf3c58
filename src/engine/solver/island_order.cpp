#include "engine/solver/island_order.hpp"

#include <algorithm>

namespace gp {

void IslandOrderScratch::release() {
  // Moved-from temporaries take the room with them; `= {}` would keep a vector's capacity.
  ends = std::vector<End>();
  sides = std::vector<Span>();
  side_count = std::vector<std::uint8_t>();
  Eigen::SparseMatrix<double>().swap(neighbours);
  order.resize(0);
}

namespace {

// The neighbours of each of the island's `count` contacts into scratch.neighbours: column k holds
// the contacts from k on that share a movable body with contact k, k itself included.
void find_neighbours(std::uint32_t count, IslandOrderScratch& scratch) {
  using Span = IslandOrderScratch::Span;
  const auto& ends = scratch.ends;
  scratch.sides.assign(2 * std::size_t{count}, Span{});
  scratch.side_count.assign(count, 0);
  std::size_t entries = count;
  for (std::uint32_t first = 0; first < ends.size();) {
    std::uint32_t last = first;
    while (last < ends.size() && ends[last].body == ends[first].body) ++last;
    for (std::uint32_t e = first; e < last; ++e) {
      const std::uint32_t k = ends[e].contact;
      scratch.sides[2 * std::size_t{k} + scratch.side_count[k]++] = {first, last};
    }
    entries += std::size_t{last - first} * (last - first) / 2;
    first = last;
  }
  Eigen::SparseMatrix<double>& neighbours = scratch.neighbours;
  neighbours.resize(count, count);
  neighbours.reserve(static_cast<Eigen::Index>(entries));
  for (std::uint32_t k = 0; k < count; ++k) {
    neighbours.startVec(k);
    // The contacts on each of its bodies, in increasing order: merged, without those before k.
    const Span s = scratch.sides[2 * std::size_t{k}];
    const Span t = scratch.side_count[k] == 2 ? scratch.sides[2 * std::size_t{k} + 1] : Span{};
    std::uint32_t e = s.first;
    std::uint32_t o = t.first;
    while (e < s.last || o < t.last) {
      const std::uint32_t row_e = e < s.last ? ends[e].contact : count;
      const std::uint32_t row_o = o < t.last ? ends[o].contact : count;
      const std::uint32_t row = std::min(row_e, row_o);
      e += row_e == row ? 1 : 0;
      o += row_o == row ? 1 : 0;
      if (row >= k) neighbours.insertBack(row, k) = 1.0;
    }
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
