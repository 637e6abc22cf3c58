#pragma once
// Items of an island (its points, or its contacts) coupled through the movable bodies they share,
// found from their ends on those bodies sorted by body: both the sparse K of an island's points
// and the graph its contacts are ordered by are built column by column from them.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gp {

/// An item's ends, by body: each its own place among the ends and its body's ends there,
/// [first, last). An item on one movable body has one side.
struct ItemEnds {
  struct Side {
    std::uint32_t own = 0, first = 0, last = 0;
  };
  Side side[2];
  std::uint32_t count = 0;
};

/// What for_each_coupled passes for an item with no end on a side.
inline constexpr std::uint32_t kNoEnd = ~std::uint32_t{0};

/// The sides of each of `items` items into `sides`, from `ends` sorted by body and then by item,
/// `item_of(end)` being an end's item. Returns the sum over the bodies of the square of their
/// ends: the entries of the matrix coupling every two items on a body, counted once per body.
template <typename End, typename ItemOf>
std::size_t find_item_ends(const std::vector<End>& ends, std::size_t items, const ItemOf& item_of,
                           std::vector<ItemEnds>& sides) {
  sides.assign(items, {});
  std::size_t entries = 0;
  for (std::uint32_t first = 0; first < ends.size();) {
    std::uint32_t last = first;
    while (last < ends.size() && ends[last].body == ends[first].body) ++last;
    for (std::uint32_t e = first; e < last; ++e) {
      ItemEnds& item = sides[item_of(ends[e])];
      item.side[item.count++] = {e, first, last};
    }
    entries += std::size_t{last - first} * (last - first);
    first = last;
  }
  return entries;
}

/// Calls visit(item, e, o) for each item coupled with the one whose sides are `sides`, itself
/// included, once and in increasing order: `e` is the place of its end on the first side, `o` on
/// the second, kNoEnd where it has none there.
template <typename End, typename ItemOf, typename Visit>
void for_each_coupled(const std::vector<End>& ends, const ItemEnds& sides, const ItemOf& item_of,
                      const Visit& visit) {
  const ItemEnds::Side f = sides.side[0];
  const ItemEnds::Side g = sides.count == 2 ? sides.side[1] : ItemEnds::Side{};
  std::uint32_t e = f.first;
  std::uint32_t o = g.first;
  while (e < f.last || o < g.last) {
    const std::uint32_t item_e = e < f.last ? item_of(ends[e]) : kNoEnd;
    const std::uint32_t item_o = o < g.last ? item_of(ends[o]) : kNoEnd;
    const std::uint32_t item = std::min(item_e, item_o);
    const std::uint32_t on_e = item_e == item ? e++ : kNoEnd;
    const std::uint32_t on_o = item_o == item ? o++ : kNoEnd;
    visit(item, on_e, on_o);
  }
}

}  // namespace gp
