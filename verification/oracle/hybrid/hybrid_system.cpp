#include "verification/oracle/hybrid/hybrid_system.hpp"

#include "verification/oracle/contact/projection.hpp"
#include "verification/oracle/model/applied_forces.hpp"

namespace gp::oracle {

HybridSystem::HybridSystem(const World& world) : world_(world), states_(world) {}

void HybridSystem::evaluate(double t, const double* y, Snapshot& out) const {
  out.motions.resize(states_.body_count());
  states_.motions_at(t, y, out.motions);
  complete(t, out);
}

void HybridSystem::evaluate(double t, std::span<const Motion> motions, Snapshot& out) const {
  out.motions.assign(motions.begin(), motions.end());
  complete(t, out);
}

void HybridSystem::complete(double t, Snapshot& out) const {
  out.time = t;
  out.linear.assign(out.motions.size(), Vec2::Zero());
  out.angular.assign(out.motions.size(), 0.0);
  applied_accelerations(world_, out.motions, out.linear, out.angular);
  out.kinematics = kinematics_of(contacts_, out.motions);
  out.forces = solve_contact_forces(world_, contacts_, out.kinematics, out.linear, out.angular);
}

void HybridSystem::derivative(double t, const double* y, double* dydt) {
  evaluate(t, y, scratch_);
  states_.derivative_of(scratch_.motions, scratch_.linear, scratch_.angular, dydt);
}

double HybridSystem::project(double t, double* y) {
  if (contacts_.empty()) return 0.0;
  scratch_.motions.resize(states_.body_count());
  states_.motions_at(t, y, scratch_.motions);
  const double left = project_onto_contacts(world_, contacts_, scratch_.motions);
  states_.values_of(scratch_.motions, y);
  return left;
}

}  // namespace gp::oracle
