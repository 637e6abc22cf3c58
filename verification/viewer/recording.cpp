#include "verification/viewer/recording.hpp"

#include "engine/scene/run.hpp"

namespace gp::verification {

namespace {

Frame frame_of(const Space& space, double t) {
  Frame f{t, {}, {}, invariants(space), {}};
  for (BodyId body = 0; body < space.body_count(); ++body) {
    f.states.push_back(space.state(body));
    f.quantities.push_back(body_quantities(space, body));
  }
  for (const Contact& c : space.contacts()) {
    const Vec2 position_a = space.state(c.body_a).position;
    for (const ContactPointState& p : space.contacts().points(c)) {
      // Speculative points that never closed carry no impulse and are not contacts to show.
      if (p.normal_impulse <= 0.0) continue;
      // The point as it was found, carried along with A since.
      f.contacts.push_back(
          {c.body_a, c.body_b, position_a + arm_a(c, p), c.normal, p.normal_impulse});
    }
  }
  return f;
}

}  // namespace

Recording record_run(Space& space, const Scene& scene) {
  Recording r;
  run_steps(
      scene,
      [&](double dt) {
        space.step(dt);
        r.impacts.insert(r.impacts.end(), space.impacts().begin(), space.impacts().end());
      },
      [&](double t) { r.frames.push_back(frame_of(space, t)); });
  return r;
}

}  // namespace gp::verification
