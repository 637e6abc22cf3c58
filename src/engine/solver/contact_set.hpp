#pragma once
// The contact constraints of a step, stored so that a contact takes room for the points it has:
// a disc's contacts have one point, and room for a second in every contact would double their
// memory.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/prefetch.hpp"
#include "engine/solver/contact.hpp"
#include "engine/trivial_room.hpp"

namespace gp {

/// Where a contact goes in a ContactSet: its index, the index of its first point, and of its
/// block (Contact::kNoBlock for one point).
struct ContactSlot {
  std::uint32_t contact = 0;
  std::uint32_t first_point = 0;
  std::uint32_t block = Contact::kNoBlock;

  /// Of points: 1 or 2 (Contact::count).
  std::size_t count() const { return block == Contact::kNoBlock ? 1 : 2; }
};

/// Where the next contact of a run of contacts goes: its index, its first point's, and the block
/// it takes if it has two points. From zero, it counts what a run takes.
struct ContactCursor {
  std::uint32_t contact = 0;
  std::uint32_t point = 0;
  std::uint32_t block = 0;

  /// The slot of the next contact, of `count` points (1 or 2), and the cursor moved past it.
  ContactSlot take(int count) {
    const ContactSlot slot{contact, point, count == 2 ? block : Contact::kNoBlock};
    contact += 1;
    point += static_cast<std::uint32_t>(count);
    block += count == 2 ? 1U : 0U;
    return slot;
  }
};

/// Contacts in the order they were appended (the solvers' order), each with its `count` points
/// stored one after the other from Contact::first_point, and the normal blocks of the two-point
/// contacts. Its arrays keep their room from step to step: a contact is initialised once, where
/// it is placed, and on whichever thread places it. They double when they must grow, and
/// fit_room cuts them back once a step's contacts are all in.
class ContactSet {
 public:
  std::size_t size() const { return end_.contact; }
  bool empty() const { return end_.contact == 0; }
  /// Of all the contacts together.
  std::size_t point_count() const { return end_.point; }
  void clear();

  Contact& operator[](std::size_t i) { return contacts_[i]; }
  const Contact& operator[](std::size_t i) const { return contacts_[i]; }
  Contact* begin() { return contacts_.data(); }
  Contact* end() { return contacts_.data() + end_.contact; }
  const Contact* begin() const { return contacts_.data(); }
  const Contact* end() const { return contacts_.data() + end_.contact; }

  std::span<ContactPointState> points(const Contact& c) {
    return {points_.data() + c.first_point, static_cast<std::size_t>(c.count())};
  }
  std::span<const ContactPointState> points(const Contact& c) const {
    return {points_.data() + c.first_point, static_cast<std::size_t>(c.count())};
  }
  /// The points of the contact placed at `slot`, found from the slot alone: read from the
  /// contact just placed, they would wait on the stores that wrote it.
  std::span<ContactPointState> points(const ContactSlot& slot) {
    return {points_.data() + slot.first_point, slot.count()};
  }

  /// Appends a contact of `count` points (1 or 2), its points value-initialised; the caller fills
  /// in the rest. A block is left as it was: the preparation (prepare_contacts) writes it whole,
  /// and cleared here it would be one more cache line the narrowphase writes, often one the other
  /// thread holds.
  Contact& append(int count);

  /// Makes room for `runs` of contacts in order after the others, each given as the cursor that
  /// counted it from zero, and turns each into the cursor of its run's first contact, from which
  /// its contacts' slots are taken in turn; place then initialises each.
  void reserve(std::span<ContactCursor> runs);
  /// The contact at `slot` (taken from a run's cursor after reserve), its points
  /// value-initialised and its block left as append leaves it. Contacts of different slots may be
  /// placed on different threads at once.
  Contact& place(const ContactSlot& slot);
  /// Asks for the cache lines that place() and the filling in of `slot` write, a few contacts
  /// ahead of them: the threads place contacts where the other core may have written last.
  void prefetch_for_placing(const ContactSlot& slot) const {
    prefetch_for_writing(contacts_.data() + slot.contact, sizeof(Contact));
    prefetch_for_writing(points_.data() + slot.first_point,
                         slot.count() * sizeof(ContactPointState));
  }

  /// Cuts the arrays to an eighth more than they hold if they grew since the last call: a step
  /// that finds a pile's contacts from none doubles them rather than copying them at every
  /// eighth more, and memory per body counts the room kept.
  void fit_room();
  /// Empties the set and frees the room of its arrays, for a space that will find no contacts
  /// for a while (one standing still).
  void release();

  /// The block of a two-point contact, filled in where it is kept.
  const NormalBlock& block(const Contact& c) const { return blocks_[c.block]; }
  NormalBlock& block(const Contact& c) { return blocks_[c.block]; }

  /// Per point of `c` [m/s]: C_R times v_rel·n before the step when the point was touching and
  /// approaching faster than the restitution threshold (it then bounces, apply_restitution
  /// driving v_rel·n up to minus this), else 0. Kept beside the points rather than in them, and
  /// only while keeps_bounce_velocities(): most scenes have no shape that bounces, and every pass
  /// over the points would carry the field.
  std::span<double> bounce_velocities(const Contact& c) {
    return {bounces_.data() + c.first_point, static_cast<std::size_t>(c.count())};
  }
  std::span<const double> bounce_velocities(const Contact& c) const {
    return {bounces_.data() + c.first_point, static_cast<std::size_t>(c.count())};
  }
  /// Gives every point a bounce velocity, each to be set by the caller, or, with `keep` false,
  /// none.
  void keep_bounce_velocities(bool keep);
  bool keeps_bounce_velocities() const { return keeps_bounces_; }

  /// Whether every contact has one point: each point then stands at its contact's own index, and
  /// the contacts can be moved about in place (reorder).
  bool single_points() const { return end_.block == 0; }
  /// Moves the contact at each index k, with its point and bounce, to index `to[k]`, in place:
  /// `to` is a permutation of the contacts' indices, and every contact has one point
  /// (single_points). `moved` is scratch.
  void reorder(std::span<const std::uint32_t> to, std::vector<bool>& moved);
  /// Undoes reorder(to, moved): each index k takes back the contact at `to[k]`.
  void restore_order(std::span<const std::uint32_t> to, std::vector<bool>& moved);

  /// Removes the contacts for which `drop(contact)` is true, keeping the others' order.
  template <typename Predicate>
  void erase_if(Predicate drop) {
    std::size_t kept = 0;
    std::size_t kept_points = 0;
    std::size_t kept_blocks = 0;
    for (const Contact& c : *this) {
      if (drop(c)) continue;
      Contact moved = c;
      moved.first_point = static_cast<std::uint32_t>(kept_points);
      for (int k = 0; k < c.count(); ++k) {
        if (keeps_bounces_) bounces_[kept_points] = bounces_[c.first_point + k];
        points_[kept_points++] = points_[c.first_point + k];
      }
      if (c.block != Contact::kNoBlock) {
        moved.block = static_cast<std::uint32_t>(kept_blocks);
        blocks_[kept_blocks++] = blocks_[c.block];
      }
      contacts_[kept++] = moved;
    }
    end_ = {static_cast<std::uint32_t>(kept), static_cast<std::uint32_t>(kept_points),
            static_cast<std::uint32_t>(kept_blocks)};
  }

 private:
  /// The bounce velocities of the contact placed at `slot`, found from the slot alone (place).
  std::span<double> bounce_velocities(const ContactSlot& slot) {
    return {bounces_.data() + slot.first_point, slot.count()};
  }
  /// Room for the contacts, points and blocks taken. Inline, with its growth out of line: it is
  /// asked for at every contact appended, and the arrays seldom grow.
  void make_room() {
    if (contacts_.size() < end_.contact || points_.size() < end_.point ||
        blocks_.size() < end_.block || (keeps_bounces_ && bounces_.size() < end_.point)) {
      grow();
    }
  }
  void grow();
  /// A contact, its point and its bounce, as reorder moves them.
  struct Single {
    Contact contact;
    ContactPointState point;
    double bounce;
  };
  Single take(std::uint32_t i) const {
    return {contacts_[i], points_[i], keeps_bounces_ ? bounces_[i] : 0.0};
  }
  void put(std::uint32_t i, const Single& single) {
    contacts_[i] = single.contact;
    contacts_[i].first_point = i;
    points_[i] = single.point;
    if (keeps_bounces_) bounces_[i] = single.bounce;
  }

  // Each array's first entries, up to end_, are in use; the rest is room.
  TrivialRoom<Contact> contacts_;
  TrivialRoom<ContactPointState> points_;
  TrivialRoom<NormalBlock> blocks_;
  std::vector<double> bounces_;  // per point, while keeps_bounces_
  ContactCursor end_;            // past the contacts, points and blocks in use
  bool grown_ = false;           // since the last fit_room
  bool keeps_bounces_ = false;
};

}  // namespace gp
