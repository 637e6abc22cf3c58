#pragma once
// The contact constraints of a step, stored so that a contact takes room for the points it has:
// a disc's contacts have one point, and room for a second in every contact would double their
// memory.

#include <cstddef>
#include <span>
#include <vector>

#include "engine/solver/contact.hpp"

namespace gp {

/// Contacts in the order they were appended (the solvers' order), each with its `count` points
/// stored one after the other from Contact::first_point, and the normal blocks of the two-point
/// contacts.
class ContactSet {
 public:
  std::size_t size() const { return contacts_.size(); }
  bool empty() const { return contacts_.empty(); }
  /// Of all the contacts together.
  std::size_t point_count() const { return points_.size(); }
  void clear();

  Contact& operator[](std::size_t i) { return contacts_[i]; }
  const Contact& operator[](std::size_t i) const { return contacts_[i]; }
  auto begin() { return contacts_.begin(); }
  auto end() { return contacts_.end(); }
  auto begin() const { return contacts_.begin(); }
  auto end() const { return contacts_.end(); }

  std::span<ContactPointState> points(const Contact& c) {
    return {points_.data() + c.first_point, static_cast<std::size_t>(c.count())};
  }
  std::span<const ContactPointState> points(const Contact& c) const {
    return {points_.data() + c.first_point, static_cast<std::size_t>(c.count())};
  }

  /// Appends a contact of `count` points (1 or 2), its points and block value-initialised; the
  /// caller fills in the rest.
  Contact& append(int count);

  /// The block of a two-point contact, as set_block left it.
  const NormalBlock& block(const Contact& c) const { return blocks_[c.block]; }
  void set_block(const Contact& c, const NormalBlock& block) { blocks_[c.block] = block; }

  /// Removes the contacts for which `drop(contact)` is true, keeping the others' order.
  template <typename Predicate>
  void erase_if(Predicate drop) {
    std::size_t kept = 0;
    std::size_t kept_points = 0;
    std::size_t kept_blocks = 0;
    for (const Contact& c : contacts_) {
      if (drop(c)) continue;
      Contact moved = c;
      moved.first_point = static_cast<std::uint32_t>(kept_points);
      for (int k = 0; k < c.count(); ++k) points_[kept_points++] = points_[c.first_point + k];
      if (c.block != Contact::kNoBlock) {
        moved.block = static_cast<std::uint32_t>(kept_blocks);
        blocks_[kept_blocks++] = blocks_[c.block];
      }
      contacts_[kept++] = moved;
    }
    contacts_.resize(kept);
    points_.resize(kept_points);
    blocks_.resize(kept_blocks);
  }

 private:
  std::vector<Contact> contacts_;
  std::vector<ContactPointState> points_;
  std::vector<NormalBlock> blocks_;
};

}  // namespace gp
