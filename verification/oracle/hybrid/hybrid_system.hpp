#pragma once
// The equations of motion between two events: every body's applied forces (the world model,
// through TM and GD models), plus the forces of the active contacts in their current modes
// (contact_forces.hpp). The active contacts change only at events, which the oracle's driver
// handles; between them this is a smooth ODE y' = f(t, y) for a SUNDIALS solver.

#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/contact/contact_forces.hpp"
#include "verification/oracle/contact/contact_kinematics.hpp"
#include "verification/oracle/hybrid/body_states.hpp"

namespace gp::oracle {

/// Everything the system knows at one (t, y).
struct Snapshot {
  double time = 0.0;
  std::vector<Motion> motions;                ///< every body
  std::vector<ContactKinematics> kinematics;  ///< every active contact
  std::vector<ContactForce> forces;           ///< every active contact
  std::vector<Vec2> linear;                   ///< every body's acceleration [m/s²]
  std::vector<double> angular;                ///< every body's angular acceleration [rad/s²]
};

class HybridSystem {
 public:
  /// `world` must outlive this.
  explicit HybridSystem(const World& world);

  const World& world() const { return world_; }
  const BodyStates& states() const { return states_; }
  std::size_t size() const { return states_.size(); }

  /// The contacts that hold, with their modes; set by the driver at events.
  const std::vector<ActiveContact>& contacts() const { return contacts_; }
  void set_contacts(std::vector<ActiveContact> contacts) { contacts_ = std::move(contacts); }

  /// The snapshot at (t, y) with the current contacts, into `out` (its storage reused).
  void evaluate(double t, const double* y, Snapshot& out) const;
  /// The snapshot of `motions` at time t: kinematics, forces and accelerations.
  void evaluate(double t, std::span<const Motion> motions, Snapshot& out) const;
  /// f(t, y) into dydt. Not reentrant: uses scratch storage.
  void derivative(double t, const double* y, double* dydt);
  /// Puts y onto the active contacts' constraints (projection.hpp); returns the largest |g| left.
  double project(double t, double* y);

 private:
  /// The rest of a snapshot whose motions are set.
  void complete(double t, Snapshot& out) const;

  const World& world_;
  BodyStates states_;
  std::vector<ActiveContact> contacts_;
  Snapshot scratch_;
};

}  // namespace gp::oracle
