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
  for (const ContactPointReport& p : space.contact_points()) {
    // Speculative points that never closed carry no impulse and are not contacts to show.
    if (p.normal_impulse <= 0.0) continue;
    f.contacts.push_back({p.body_a, p.body_b, p.point, p.normal, p.normal_impulse});
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
