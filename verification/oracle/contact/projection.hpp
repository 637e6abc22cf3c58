#pragma once
// Holding the active constraints to round-off. Integrating g̈ = 0 keeps a contact's gap at zero
// only to the solver's tolerance; the oracle removes that drift after every step (CVODE's
// projection with BDF, a post-step function with ARKODE) by the least change, in the metric of the
// bodies' masses, that puts each active gap at zero, then each gap rate and each sticking slip.

#include <span>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// Moves the positions of `motions` (every body's, in place) onto g = 0 at every contact of
/// `contacts`. Returns the largest |g| [m] left, after up to a few Newton iterations (the gaps are
/// not linear in the angles).
double project_positions(const World& world, std::span<const ActiveContact> contacts,
                         std::span<Motion> motions);

/// Moves `motions` onto g = 0 (project_positions), then ġ = 0 and, for sticking contacts, s = 0
/// at every contact of `contacts`. Returns the largest |g| [m] left.
double project_onto_contacts(const World& world, std::span<const ActiveContact> contacts,
                             std::span<Motion> motions);

}  // namespace gp::oracle
