#include "engine/solver/contact_set.hpp"

#include "engine/capacity.hpp"

namespace gp {

void ContactSet::clear() {
  contacts_.clear();
  points_.clear();
  blocks_.clear();
}

Contact& ContactSet::append(int count) {
  // Grown as contacts come rather than for every candidate pair, of which many make none.
  reserve_for(contacts_, contacts_.size() + 1);
  reserve_for(points_, points_.size() + static_cast<std::size_t>(count));
  Contact& c = contacts_.emplace_back();
  c.first_point = static_cast<std::uint32_t>(points_.size());
  c.block = Contact::kNoBlock;
  if (count == 2) {
    reserve_for(blocks_, blocks_.size() + 1);
    c.block = static_cast<std::uint32_t>(blocks_.size());
    blocks_.emplace_back();
  }
  for (int k = 0; k < count; ++k) points_.emplace_back();
  return c;
}

}  // namespace gp
