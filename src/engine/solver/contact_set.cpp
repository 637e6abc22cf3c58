#include "engine/solver/contact_set.hpp"

#include <algorithm>

#include "engine/capacity.hpp"

namespace gp {

namespace {

// Room for at least `count` entries, twice the room held when it must grow: a step that finds a
// pile's contacts from none would otherwise grow it at every eighth more.
template <typename T>
void room_for(TrivialRoom<T>& entries, std::size_t count) {
  if (entries.size() < count) entries.resize(std::max(count, 2 * entries.size()));
}

// The room of `entries` cut to grown_room of the `used` first ones, if it holds more than that.
template <typename T>
void fit(TrivialRoom<T>& entries, std::size_t used) {
  if (entries.size() > grown_room(used)) entries.resize(grown_room(used));
}

}  // namespace

void ContactSet::clear() {
  end_ = {};
  keep_bounce_velocities(false);
}

void ContactSet::grow() {
  room_for(contacts_, end_.contact);
  room_for(points_, end_.point);
  room_for(blocks_, end_.block);
  if (keeps_bounces_) keep_bounce_velocities(true);
  grown_ = true;
}

void ContactSet::fit_room() {
  if (!grown_) return;
  grown_ = false;
  fit(contacts_, end_.contact);
  fit(points_, end_.point);
  fit(blocks_, end_.block);
}

void ContactSet::release() {
  clear();
  grown_ = false;
  contacts_.resize(0);
  points_.resize(0);
  blocks_.resize(0);
  // A moved-from temporary takes the room with it.
  bounces_ = std::vector<double>();
}

void ContactSet::keep_bounce_velocities(bool keep) {
  keeps_bounces_ = keep;
  if (!keep) {
    bounces_.clear();
    return;
  }
  reserve_for(bounces_, end_.point);
  bounces_.resize(end_.point);
}

Contact& ContactSet::append(int count) {
  const ContactSlot slot = end_.take(count);
  make_room();
  return place(slot);
}

void ContactSet::reserve(std::span<ContactCursor> runs) {
  for (ContactCursor& run : runs) {
    const ContactCursor start = end_;
    end_ = {end_.contact + run.contact, end_.point + run.point, end_.block + run.block};
    run = start;
  }
  make_room();
}

Contact& ContactSet::place(const ContactSlot& slot) {
  Contact& c = contacts_[slot.contact];
  c.shape_a = c.shape_b = 0;
  c.body_a = c.body_b = 0;
  c.normal = Vec2::Zero();
  c.friction = 0.0;
  c.first_point = slot.first_point;
  c.block = slot.block;
  // A point at a time, each of a size known when compiled, so that it is cleared by stores in
  // place: cleared as a run of points of either size, by a call to memset, the narrowphase of a
  // box pile took a sixth longer.
  ContactPointState* const first = points_.data() + slot.first_point;
  first[0] = ContactPointState{};
  if (slot.count() == 2) first[1] = ContactPointState{};
  if (keeps_bounces_) std::ranges::fill(bounce_velocities(slot), 0.0);
  return c;
}

void ContactSet::reorder(std::span<const std::uint32_t> to, std::vector<bool>& moved) {
  moved.assign(size(), false);
  // Cycle by cycle: each contact goes to to[its index], taking the place of the one there.
  for (std::uint32_t start = 0; start < size(); ++start) {
    if (moved[start]) continue;
    Single held = take(start);
    for (std::uint32_t next = to[start]; next != start; next = to[next]) {
      const Single displaced = take(next);
      put(next, held);
      moved[next] = true;
      held = displaced;
    }
    put(start, held);
    moved[start] = true;
  }
}

void ContactSet::restore_order(std::span<const std::uint32_t> to, std::vector<bool>& moved) {
  moved.assign(size(), false);
  // Cycle by cycle: each index takes from the next of its cycle, the last from the first, held.
  for (std::uint32_t start = 0; start < size(); ++start) {
    if (moved[start]) continue;
    const Single first = take(start);
    std::uint32_t i = start;
    for (std::uint32_t next = to[i]; next != start; i = next, next = to[i]) {
      put(i, take(next));
      moved[i] = true;
    }
    put(i, first);
    moved[i] = true;
  }
}

}  // namespace gp
