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
  size_ = 0;
  point_count_ = 0;
  block_count_ = 0;
  keep_bounce_velocities(false);
}

ContactSlot ContactSet::take(std::uint8_t count) {
  const ContactSlot slot{
      static_cast<std::uint32_t>(size_++), static_cast<std::uint32_t>(point_count_),
      count == 2 ? static_cast<std::uint32_t>(block_count_++) : Contact::kNoBlock};
  point_count_ += count;
  return slot;
}

void ContactSet::grow() {
  room_for(contacts_, size_);
  room_for(points_, point_count_);
  room_for(blocks_, block_count_);
  if (keeps_bounces_) keep_bounce_velocities(true);
  grown_ = true;
}

void ContactSet::fit_room() {
  if (!grown_) return;
  grown_ = false;
  fit(contacts_, size_);
  fit(points_, point_count_);
  fit(blocks_, block_count_);
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
  reserve_for(bounces_, point_count_);
  bounces_.resize(point_count_);
}

Contact& ContactSet::append(int count) {
  const ContactSlot slot = take(static_cast<std::uint8_t>(count));
  make_room();
  return place(slot);
}

void ContactSet::reserve(std::span<const std::uint8_t> counts, std::span<ContactSlot> slots) {
  for (std::size_t i = 0; i < counts.size(); ++i) {
    slots[i] = counts[i] == 0 ? ContactSlot{} : take(counts[i]);
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

}  // namespace gp
