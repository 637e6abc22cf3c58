#pragma once
// A run of a scene recorded for the viewer: every body's state and SRS quantities at each output
// instant (the instants of `gamephysics simulate`, so that the page and the CSV agree row for
// row), every impact resolved at its time of impact, and the contacts that pushed at each instant.

#include <vector>

#include "engine/space.hpp"
#include "scene/scene.hpp"
#include "verification/quantities/mechanical_quantities.hpp"

namespace gp::verification {

/// A contact point whose solver impulse was positive in the last sub-step before an instant.
struct ContactPoint {
  BodyId body_a;
  BodyId body_b;
  Vec2 point;      ///< m, world: body A's deepest point, placed by A's state at the instant
  Vec2 normal;     ///< unit, from B towards A
  double impulse;  ///< N·s, the normal impulse accumulated over that sub-step
};

/// The space at one output instant.
struct Frame {
  double time;                             ///< s
  std::vector<BodyState> states;           ///< per body, in BodyId order
  std::vector<BodyQuantities> quantities;  ///< per body (zero for non-dynamic bodies)
  Invariants totals;                       ///< the sums over the dynamic bodies
  std::vector<ContactPoint> contacts;      ///< resting and speculative contacts that pushed
};

struct Recording {
  std::vector<Frame> frames;    ///< at the output instants of the scene, t = 0 first
  std::vector<Impact> impacts;  ///< every impact of the run, in time order
};

/// Runs `space`, built from `scene` and still at t = 0, to the end of the scene, as run_scene
/// does. Throws NumericalError when a state becomes non-finite.
Recording record_run(Space& space, const Scene& scene);

}  // namespace gp::verification
