#pragma once
// The SUNDIALS oracle: an independent, high-accuracy solution of a Space's equations of motion,
// to check the game integrators against. It integrates the whole ODE system of the space —
// dp/dt = v, dϕ/dt = ω with dv/dt, dω/dt from the space's own ForceModel (IM:transMot,
// IM:rotMot) — with an adaptive solver at tight tolerances, and treats every collision as an
// event located to solver precision and resolved by IM:col2D.

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "engine/space.hpp"
#include "verification/oracle/domain_error.hpp"

namespace gp::verification {

/// The integrators of the oracle: two independent families, so that they can vouch for each
/// other.
enum class OracleMethod {
  CvodeAdams,  ///< CVODE, variable-order (1–12) Adams–Moulton with functional iteration
  CvodeBdf,    ///< CVODE, variable-order (1–5) BDF with Newton iteration on a dense Jacobian
  ArkodeErk,   ///< ARKODE ERKStep, explicit Fehlberg 13(7)8 Runge–Kutta pair (order 8)
};

/// "cvode-adams", "cvode-bdf", "arkode-erk".
std::string_view oracle_method_name(OracleMethod method);
/// The method named `name`, or nothing.
std::optional<OracleMethod> oracle_method_from_name(std::string_view name);

struct OracleOptions {
  OracleMethod method = OracleMethod::CvodeAdams;
  double rtol = 1e-10;  ///< relative tolerance [1], > 0; down to 1e-12 is meaningful
  /// Absolute tolerance of every component (m, rad, m/s, rad/s), > 0.
  double atol = 1e-10;
  /// m, ≥ 0: shapes closer than this count as touching. A pair touching at the start or after an
  /// impact must be separating fast enough to get farther apart than this (else: resting contact).
  double contact_tolerance = 1e-9;
  /// Most impacts in a run (a bound on the work, and the first guard against Zeno sequences).
  std::size_t max_events = 1000;
  /// A Zeno sequence: `zeno_events` impacts within `zeno_window` [s].
  std::size_t zeno_events = 50;
  double zeno_window = 1e-6;
  /// Most solver steps in a run (a bound on the work); more is a solver failure.
  long max_steps = 10'000'000;
};

/// An impact resolved at its time of contact (IM:col2D).
struct OracleEvent {
  double time;  ///< t_c [s]
  BodyId body_a;
  BodyId body_b;
  Vec2 normal;     ///< unit, from B towards A
  Vec2 point;      ///< m, world: the contact point (the midpoint of an edge-to-edge contact)
  double impulse;  ///< j ≥ 0 [N·s], on A along the normal (−j n on B)
};

struct OracleResult {
  std::vector<double> times;                   ///< s: the output instants asked for
  std::vector<std::vector<BodyState>> states;  ///< states[k][body]: every body at times[k]
  std::vector<OracleEvent> events;             ///< in time order
  long steps = 0;                              ///< solver steps taken, for the curious
};

/// Integrates `space` from space.time() to the last of `output_times` (non-decreasing, each ≥
/// space.time(), in s) and returns the state of every body at each of them, orientation in
/// [0, 2π). Dynamic bodies follow the ODE; kinematic bodies move at their constant velocities;
/// static bodies stay put. Every pair of shapes of different bodies, one of them dynamic, is
/// watched: when its signed distance falls to zero while the pair approaches, IM:col2D is applied
/// at the contact point and normal of gp::collide (one point; the midpoint of two), with
/// C_R = max of the two shapes' restitutions and no resting threshold, and the integration
/// restarts from the new velocities. IM:col2D is frictionless: an impact of shapes with friction
/// whose contact points slide is refused.
/// The solver is stopped often enough that no pair can pass through another between two looks
/// of the root finder (CollisionWatch::horizon); only a grazing impact, whose overlap is shorter
/// than a tenth of the shapes' half-thicknesses, can be missed, and then an overlap at an output
/// instant is reported. rtol bounds the error of each step: over a long run the global error is
/// typically 10 to 1000 times rtol (a period of a circular orbit at rtol 1e-12: 1e-9 relative by
/// Adams, 1e-8 by ERK; 1e-14 brings both under 1e-9). The space is not modified.
/// Throws OracleDomainError when the scene leaves the oracle's domain (see OracleDomainError),
/// std::invalid_argument for bad options or output times.
OracleResult run_oracle(const Space& space, std::span<const double> output_times,
                        const OracleOptions& options = {});

}  // namespace gp::verification
