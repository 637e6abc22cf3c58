#pragma once
// The bodies of a colour of one-point contacts, for the tests of the kernels that take a colour's
// contacts four at a time: contact i joins bodies 1 + 2i and 2 + 2i, but for the odd ones, whose
// B is static body 0, shared as a colour's contacts may share a static body. Eleven contacts: two
// groups of four and three left over.

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "engine/core.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp::test {

/// Contacts in the colour.
constexpr std::size_t kColourContacts = 11;
/// Bodies: the static one, then two a contact.
constexpr std::size_t kColourBodies = 1 + 2 * kColourContacts;

/// Contact i's A and B.
inline BodyId colour_body_a(std::uint32_t i) {
  return 1 + 2 * i;
}
inline BodyId colour_body_b(std::uint32_t i) {
  return i % 2 == 1 ? 0 : 2 + 2 * i;
}

/// The colour's bodies' inverse masses [1/kg] and moments [1/(kg·m²)]: random from 0.2 to 3, but
/// body 0's, 0 (static).
inline BodyInertia random_colour_inertia(std::mt19937_64& random) {
  std::uniform_real_distribution<double> positive(0.2, 3.0);
  BodyInertia inertia;
  inertia.inverse_mass.assign(kColourBodies, 0.0);
  inertia.inverse_moment.assign(kColourBodies, 0.0);
  for (std::size_t b = 1; b < kColourBodies; ++b) {
    inertia.inverse_mass[b] = positive(random);
    inertia.inverse_moment[b] = positive(random);
  }
  return inertia;
}

/// What a test's colour holds: the random numbers it is drawn from, its bodies' inertias
/// (random_colour_inertia) and states, and its contacts, `indices` into `set`.
struct RandomColour {
  explicit RandomColour(std::uint64_t seed) : random(seed), inertia(random_colour_inertia(random)) {
    state.resize(kColourBodies);
  }

  std::mt19937_64 random;
  std::uniform_real_distribution<double> unit{-1.0, 1.0};
  std::uniform_real_distribution<double> positive{0.2, 3.0};
  BodyInertia inertia;
  MotionState state;
  ContactSet set;
  std::vector<std::uint32_t> indices;
};

}  // namespace gp::test
