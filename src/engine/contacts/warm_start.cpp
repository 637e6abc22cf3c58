#include "engine/contacts/warm_start.hpp"

#include "engine/capacity.hpp"

namespace gp {

void keep_impulses(const std::vector<Contact>& contacts, std::vector<WarmStart>& kept) {
  kept.clear();
  reserve_for(kept, contacts.size());
  for (const Contact& c : contacts) {
    WarmStart w{c.key(), c.count, {}};
    for (int k = 0; k < c.count; ++k) {
      w.points[k] = {c.points[k].id, c.points[k].normal_impulse, c.points[k].tangent_impulse};
    }
    kept.push_back(w);
  }
}

}  // namespace gp
