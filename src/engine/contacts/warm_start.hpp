#pragma once
// What a step's contacts hand to the next step: per point, the impulses the solver accumulated,
// from which the same point of the next step starts (warm starting). The next step reads nothing
// else of a contact, and a whole Contact is several times larger.

#include <array>
#include <cstdint>
#include <vector>

#include "engine/collision/contact.hpp"
#include "engine/contacts/contact.hpp"

namespace gp {

/// The accumulated impulses of one contact point.
struct PointImpulses {
  FeatureId id;
  double normal;   ///< N·s
  double tangent;  ///< N·s
};

/// The accumulated impulses of one contact, found again by its pair of shapes.
struct WarmStart {
  std::uint64_t key;  ///< Contact::key
  int count;
  std::array<PointImpulses, 2> points;
};

/// Replaces `kept` by the impulses of `contacts`, in the same order.
void keep_impulses(const std::vector<Contact>& contacts, std::vector<WarmStart>& kept);

}  // namespace gp
