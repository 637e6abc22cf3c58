#pragma once
// The bound on events that keeps every oracle run finite: an inelastic ball on the ground
// bounces infinitely often in finite time (a Zeno sequence), and an event-driven integrator
// would follow it forever. The rest speed ends such sequences (OracleOptions); this guard catches
// any it does not.

#include <cstddef>
#include <deque>
#include <string>

#include "verification/oracle/oracle.hpp"

namespace gp::oracle {

class ZenoGuard {
 public:
  explicit ZenoGuard(const verification::OracleOptions& options);

  /// Counts an event at time t [s] (times non-decreasing), `what` naming it for the message
  /// ("an impact of bodies 'ball' and 'ground'"). Throws OracleDomainError when there have been
  /// more than max_events events, or zeno_events of them within zeno_window seconds.
  void record(double t, const std::string& what);

 private:
  std::size_t max_events_;
  std::size_t zeno_events_;
  double zeno_window_;
  std::size_t count_ = 0;
  std::deque<double> recent_;  // the times of the last zeno_events events
};

}  // namespace gp::oracle
