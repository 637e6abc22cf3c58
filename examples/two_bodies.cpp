// Two bodies in 30 lines (NFR:Usability): a ball falls onto a box resting on the ground.
#include <cstdio>

#include "gamephysics/gamephysics.hpp"

int main() {
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};  // m/s²
  gp::Space space(settings);

  gp::BodyDef ground;
  ground.name = "ground";
  ground.type = gp::BodyType::Static;
  ground.shapes.push_back({gp::Shape::segment({-10.0, 0.0}, {10.0, 0.0})});
  space.add_body(ground);

  gp::BodyDef ball;
  ball.name = "ball";
  ball.position = {0.0, 5.0};  // m
  ball.shapes.push_back({gp::Shape::circle(0.5), /*restitution=*/0.8});
  const gp::BodyId id = space.add_body(ball);

  for (int step = 0; step <= 120; ++step) {
    if (step % 30 == 0) {
      const gp::BodyState s = space.state(id);
      std::printf("t=%.2f s  y=%.4f m  vy=%.4f m/s\n", space.time(), s.position.y(),
                  s.velocity.y());
    }
    space.step(1.0 / 60.0);  // s
  }
}
