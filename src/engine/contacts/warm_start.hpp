#pragma once
// What a step's contacts hand to the next step: per point, the impulses the solver accumulated,
// from which the same point of the next step starts (warm starting). The next step reads nothing
// else of a contact, and a whole contact point is several times larger.

#include <cstdint>
#include <vector>

#include "engine/collision/contact.hpp"
#include "engine/contacts/contact_set.hpp"

namespace gp {

/// The accumulated impulses of one contact point, found again by its contact's pair of shapes
/// and its pair of features.
struct WarmStart {
  std::uint64_t key;  ///< Contact::key
  FeatureId id;
  double normal;   ///< N·s
  double tangent;  ///< N·s
};

/// Replaces `kept` by the impulses of the points of `contacts`, in the same order.
void keep_impulses(const ContactSet& contacts, std::vector<WarmStart>& kept);

}  // namespace gp
