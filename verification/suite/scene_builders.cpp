#include "verification/suite/scene_builders.hpp"

namespace gp::verification {

Scene make_scene(const Vec2& gravity, double dt, double duration) {
  Scene s;
  s.settings.gravity = gravity;
  s.dt = dt;
  s.duration = duration;
  s.output_dt = dt;
  return s;
}

BodyDef disc(const std::string& name, const Vec2& position, const Vec2& velocity, double radius,
             double restitution, double density) {
  BodyDef b;
  b.name = name;
  b.position = position;
  b.velocity = velocity;
  b.shapes.push_back({Shape::circle(radius), restitution, 0.0, density});
  return b;
}

BodyDef box(const std::string& name, const Vec2& position, double width, double height,
            double friction, double density) {
  BodyDef b;
  b.name = name;
  b.position = position;
  b.shapes.push_back({Shape::box(width, height), 0.0, friction, density});
  return b;
}

BodyDef wall(const std::string& name, const Vec2& a, const Vec2& b, double restitution,
             double friction) {
  BodyDef w;
  w.name = name;
  w.type = BodyType::Static;
  w.shapes.push_back({Shape::segment(a, b), restitution, friction});
  return w;
}

Scene rain100() {
  Scene s = make_scene({0.0, -9.81}, 1.0 / 60, 1.5);
  s.bodies.push_back(wall("floor", {-20.0, 0.0}, {20.0, 0.0}, 0.9));
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) {
      // Staggered by 1 cm along a row, so that no two discs land at the same instant.
      s.bodies.push_back(disc("drop" + std::to_string(10 * i + j),
                              {-9.0 + 2.0 * j, 5.0 + 2.0 * i + 0.01 * j}, Vec2::Zero(), 0.5, 0.9));
    }
  }
  return s;
}

}  // namespace gp::verification
