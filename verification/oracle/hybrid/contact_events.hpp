#pragma once
// What happens at an event of the hybrid integration, and at the start: which contacts hold
// afterwards, the impacts among them, their modes of friction, and the state put back onto the
// constraints. The driver (oracle.cpp) calls it wherever the root finder stopped.

#include <span>
#include <string>
#include <vector>

#include "verification/oracle/hybrid/event_watch.hpp"
#include "verification/oracle/hybrid/hybrid_system.hpp"
#include "verification/oracle/oracle.hpp"

namespace gp::oracle {

class ContactEvents {
 public:
  /// All must outlive this.
  ContactEvents(HybridSystem& system, EventWatch& watch,
                const verification::OracleOptions& options);

  /// At the start (time t, state y): every pair closer than the contact tolerance touches; an
  /// overlap deeper than it is outside the domain.
  void start(double t, double* y, std::vector<verification::OracleEvent>& impacts);

  /// At a stop of the root finder at time t, state y, with `crossed` non-zero for each root
  /// function (of `watch` as armed) that crossed: the contacts after the event. Writes the new
  /// state into y and appends impacts.
  void handle(double t, double* y, std::span<const int> crossed,
              std::vector<verification::OracleEvent>& impacts);

  /// Throws OracleDomainError when a pair without contact overlaps by more than the contact
  /// tolerance at time t, state y: an impact the root finder missed.
  void require_apart(double t, const double* y) const;

  /// Throws OracleDomainError when an active contact of `snapshot` (the system's, at a stop of
  /// the solver) pulls with f_n below twice the force floor (EventWatch::force_floor): a
  /// lift-off whose root function started negative, which the root finder can never see. Not
  /// where the forces are not unique: their least-norm share may pull where others would not.
  void require_pushing(const Snapshot& snapshot) const;

  /// Notes the largest |gap| of an active contact at time t, state y, as drift.
  void note_drift(double t, const double* y);
  /// m: the largest |gap| of an active contact noted, or left by a projection at an event.
  double largest_drift() const { return largest_drift_; }

  /// "bodies 'A' and 'B'", for messages.
  std::string describe(std::size_t a, std::size_t b) const;

 private:
  /// Adds to `contacts` the touching features of pair `p` at `motions` not among them yet.
  void detect(std::size_t p, std::span<const Motion> motions,
              std::vector<ActiveContact>& contacts) const;
  /// Impacts, separation, modes and projection for `candidates` at time t; the result becomes
  /// the system's contacts and y the projected state. Pairs of `candidates` or of the contacts
  /// before that part slower than the rest speed are released (EventWatch::release).
  void settle(double t, std::vector<Motion>& motions, std::vector<ActiveContact> candidates,
              double* y, std::vector<verification::OracleEvent>& impacts);

  HybridSystem& system_;
  EventWatch& watch_;
  verification::OracleOptions options_;
  double largest_drift_ = 0.0;
};

}  // namespace gp::oracle
