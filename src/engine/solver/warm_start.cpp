#include "engine/solver/warm_start.hpp"

#include "engine/capacity.hpp"
#include "engine/collision/body_shapes.hpp"

namespace gp {

static_assert(BodyShapes::kMaxShapes <= std::size_t{1} << WarmStart::kShapeBits,
              "a shape index must fit in a warm start's key");

void keep_impulses(const ContactSet& contacts, std::vector<WarmStart>& kept) {
  kept.clear();
  reserve_for(kept, contacts.point_count());
  for (const Contact& c : contacts) {
    const std::uint64_t pair = WarmStart::pair_key({c.shape_a, c.shape_b});
    for (const ContactPointState& p : contacts.points(c)) {
      kept.push_back({WarmStart::point_key(pair, p.id.key()), p.normal_impulse, p.tangent_impulse});
    }
  }
}

}  // namespace gp
