#include "engine/solver/contact_batches.hpp"

#include <array>
#include <bit>

namespace gp {

namespace {

// Colours a large island's contacts take; a contact that finds all of them taken by its bodies
// goes to one more, whose contacts are solved one after the other.
constexpr std::size_t kColours = 64;

}  // namespace

void ContactBatches::build(const ContactSet& contacts, const BodyInertia& inertia,
                           std::size_t coloured_above) {
  islands_.find(contacts, inertia);
  order_.clear();
  task_end_.clear();
  stage_end_.clear();
  const std::size_t bodies = inertia.inverse_mass.size();
  const auto large = [this, coloured_above](std::size_t root) {
    return coloured_above > 0 &&
           islands_.island_end[root] - islands_.island_start[root] > coloured_above;
  };
  bool any_large = false;
  for (std::size_t r = 0; r < bodies; ++r) {
    const std::uint32_t start = islands_.island_start[r];
    const std::uint32_t end = islands_.island_end[r];
    any_large = any_large || large(r);
    if (start == end || large(r)) continue;
    order_.insert(order_.end(), islands_.order.begin() + start, islands_.order.begin() + end);
    task_end_.push_back(static_cast<std::uint32_t>(order_.size()));
  }
  stage_end_.push_back(static_cast<std::uint32_t>(task_end_.size()));
  if (!any_large) return;

  // Greedy colouring in the contacts' order: each contact takes the lowest colour that no other
  // contact of its movable bodies has. Static and kinematic bodies take any number of contacts
  // of a colour, as the solver only reads their motion.
  colours_.assign(bodies, 0);
  colour_.resize(contacts.size());
  std::array<std::uint32_t, kColours + 3> next{};  // counts, then starts
  for (std::size_t r = 0; r < bodies; ++r) {
    if (!large(r)) continue;
    for (std::uint32_t e = islands_.island_start[r]; e < islands_.island_end[r]; ++e) {
      const Contact& c = contacts[islands_.order[e]];
      const bool a = movable(inertia, c.body_a);
      const bool b = movable(inertia, c.body_b);
      const std::uint64_t taken = (a ? colours_[c.body_a] : 0) | (b ? colours_[c.body_b] : 0);
      const auto colour = static_cast<std::size_t>(std::countr_one(taken));
      if (colour < kColours) {
        if (a) colours_[c.body_a] |= std::uint64_t{1} << colour;
        if (b) colours_[c.body_b] |= std::uint64_t{1} << colour;
      }
      colour_[islands_.order[e]] = static_cast<std::uint8_t>(colour);
      ++next[colour + 2];
    }
  }
  // Counting sort by colour, each colour's contacts in the contacts' order.
  const auto base = static_cast<std::uint32_t>(order_.size());
  next[1] = base;
  for (std::size_t k = 2; k < next.size(); ++k) next[k] += next[k - 1];
  order_.resize(next.back());
  for (std::size_t r = 0; r < bodies; ++r) {
    if (!large(r)) continue;
    for (std::uint32_t e = islands_.island_start[r]; e < islands_.island_end[r]; ++e) {
      const std::uint32_t i = islands_.order[e];
      order_[next[colour_[i] + 1]++] = i;
    }
  }
  // next[k + 1] is now the end of colour k.
  for (std::size_t k = 0; k <= kColours; ++k) {
    const std::uint32_t begin = k == 0 ? base : next[k];
    const std::uint32_t end = next[k + 1];
    if (k < kColours) {
      for (std::uint32_t e = begin; e < end; ++e) task_end_.push_back(e + 1);
    } else if (end > begin) {
      task_end_.push_back(end);
    }
    stage_end_.push_back(static_cast<std::uint32_t>(task_end_.size()));
  }
}

}  // namespace gp
