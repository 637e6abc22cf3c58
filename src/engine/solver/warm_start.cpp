#include "engine/solver/warm_start.hpp"

#include "engine/capacity.hpp"
#include "engine/collision/body_shapes.hpp"
#include "engine/threads.hpp"

namespace gp {

namespace {

// Contacts a thread takes at a time: a contact costs a few nanoseconds to keep, a task about a
// microsecond to hand out.
constexpr std::size_t kContactsPerTask = 2048;
// Fewer contacts are kept on one thread: a few microseconds' work, less than waking a worker.
constexpr std::size_t kParallelContacts = 2 * kContactsPerTask;

}  // namespace

static_assert(BodyShapes::kMaxShapes <= std::size_t{1} << WarmStart::kShapeBits,
              "a shape index must fit in a warm start's key");

void keep_impulses(const ContactSet& contacts, std::vector<WarmStart>& kept) {
  reserve_for(kept, contacts.point_count());
  kept.resize(contacts.point_count());
  // A contact's points follow those of the contact before it, so each point's warm start goes
  // to its own index, and the contacts can be kept side by side.
  for_blocks(
      contacts.size(), kContactsPerTask, contacts.size() < kParallelContacts,
      [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
          const Contact& c = contacts[i];
          const std::uint64_t pair = WarmStart::pair_key({c.shape_a, c.shape_b});
          WarmStart* out = kept.data() + c.first_point;
          for (const ContactPointState& p : contacts.points(c)) {
            *out++ = {WarmStart::point_key(pair, p.id.key()), p.normal_impulse, p.tangent_impulse};
          }
        }
      });
}

}  // namespace gp
