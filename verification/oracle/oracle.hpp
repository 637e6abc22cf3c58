#pragma once
// The SUNDIALS oracle: an independent, high-accuracy solution of a scene's equations of motion,
// to check the game engine against. It reads the scene (the scene library, which it shares with
// the engine: reading is data, not physics) and computes everything else itself: mass
// properties through the DD models, forces through the TM and GD models, its own contact
// geometry (verification/oracle/model, geometry). It integrates the rigid bodies as a hybrid
// system: smooth motion between events with the forces of the active contacts (unilateral, with
// Coulomb friction), found at the acceleration level; events located by root finding to solver
// precision: contact onset, lift-off, stick to slip, slip to stick, a vertex leaving its edge;
// impacts resolved by IM:col2D (or Newton's law at several points at once). It never includes
// or links the engine (src/engine); the build enforces that (verification/oracle/CMakeLists.txt).

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "scene/body_state.hpp"
#include "scene/scene.hpp"
#include "verification/oracle/domain_error.hpp"

namespace gp::verification {

/// The integrators of the oracle: two independent families, so that they can vouch for each
/// other.
enum class OracleMethod {
  CvodeAdams,  ///< CVODE, variable-order (1–12) Adams–Moulton with functional iteration
  CvodeBdf,    ///< CVODE, variable-order (1–5) BDF with Newton iteration on a dense Jacobian
  ArkodeErk,   ///< ARKODE ERKStep, explicit Fehlberg 13(7)8 Runge–Kutta pair (order 8)
  /// Moreau–Jean time-stepping at a fixed step (stepping/), first order: the reference for piles,
  /// whose events the three above cannot afford; rtol and atol do not apply, `step` does.
  TimeStepping,
};

/// "cvode-adams", "cvode-bdf", "arkode-erk", "time-stepping".
std::string_view oracle_method_name(OracleMethod method);
/// The method named `name`, or nothing.
std::optional<OracleMethod> oracle_method_from_name(std::string_view name);

struct OracleOptions {
  OracleMethod method = OracleMethod::CvodeAdams;
  double rtol = 1e-12;  ///< relative tolerance [1], > 0; down to 1e-14 is meaningful
  /// Absolute tolerance of every component (m, rad, m/s, rad/s), > 0.
  double atol = 1e-12;
  /// m, > 0: shapes closer than this at an event touch; an overlap deeper than this at an output
  /// instant is an impact the oracle missed, and fails the run.
  double contact_tolerance = 1e-9;
  /// m/s, > 0: an arrival slower than this ends without a bounce (C_R taken as 0) and the
  /// contact holds; a bounce this slow would rise v²/2g ≈ 5e-10 m under Earth's gravity. It
  /// is also what ends a Zeno sequence of ever smaller bounces.
  double rest_speed = 1e-4;
  /// m/s, > 0: a contact point moving apart or slipping slower than this is at rest (round-off
  /// of the impulses and projections, not motion).
  double speed_tolerance = 1e-9;
  /// Most events in a run (a bound on the work, and a guard against Zeno sequences).
  std::size_t max_events = 10000;
  /// A Zeno sequence: `zeno_events` events within `zeno_window` [s].
  std::size_t zeno_events = 50;
  double zeno_window = 1e-6;
  /// s, > 0: TimeStepping's largest step h (each interval between output instants is cut into
  /// equal steps no longer than this).
  double step = 1e-3;
  /// Most solver steps in a run (a bound on the work); more is a solver failure.
  long max_steps = 10'000'000;

  bool operator==(const OracleOptions&) const = default;
};

/// An impact resolved at its time of contact (IM:col2D, or Newton's law at several points).
struct OracleEvent {
  double time;  ///< t_c [s]
  std::size_t body_a;
  std::size_t body_b;
  Vec2 normal;     ///< unit, from B towards A
  Vec2 point;      ///< m, world: the contact point
  double impulse;  ///< j ≥ 0 [N·s], on A along the normal (−j n on B)
};

struct OracleResult {
  std::vector<double> times;                   ///< s: the output instants asked for
  std::vector<std::vector<BodyState>> states;  ///< states[k][body]: every body at times[k]
  std::vector<OracleEvent> events;             ///< impacts, in time order
  long contact_changes = 0;  ///< events that changed the contacts without an impulse
  long steps = 0;            ///< solver steps taken, for the curious
  /// m: the largest |gap| of an active contact at an output instant or event (the drift); with
  /// TimeStepping, the deepest overlap of a contact at a step's start (first order in the step).
  double largest_drift = 0.0;
};

/// Integrates the bodies of `scene` from t = 0 to the last of `output_times` (non-decreasing,
/// each ≥ 0, in s) and returns the state of every body at each of them: centre of mass,
/// orientation in [0, 2π), velocities. Static bodies stay put, kinematic bodies move at their
/// constant velocities. Touching shapes at the start are in contact. Throws OracleDomainError
/// when the scene leaves the oracle's domain (an impact that gains energy, a contact
/// problem with no solution, a Zeno sequence, a solver failure, an overlap it missed),
/// std::invalid_argument for bad options or output times, and InputError for bodies the SRS
/// constraints refuse.
OracleResult run_oracle(const Scene& scene, std::span<const double> output_times,
                        const OracleOptions& options = {});

}  // namespace gp::verification
