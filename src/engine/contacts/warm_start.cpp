#include "engine/contacts/warm_start.hpp"

#include "engine/capacity.hpp"

namespace gp {

void keep_impulses(const ContactSet& contacts, std::vector<WarmStart>& kept) {
  kept.clear();
  reserve_for(kept, contacts.point_count());
  for (const Contact& c : contacts) {
    for (const ContactPointState& p : contacts.points(c)) {
      kept.push_back({c.key(), p.id, p.normal_impulse, p.tangent_impulse});
    }
  }
}

}  // namespace gp
