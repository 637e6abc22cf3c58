#pragma once
// Small scenes built in code for the oracle's tests (discs, a ground line, gravity), and the
// options that run them.

#include <string>
#include <utility>
#include <vector>

#include "scene/scene.hpp"
#include "verification/oracle/oracle.hpp"

namespace gp::test {

/// A dynamic disc of `radius` [m] and `mass` [kg] at `position` [m] moving at `velocity` [m/s],
/// its surface of restitution `restitution`.
inline BodyDef disc(const std::string& name, const Vec2& position, const Vec2& velocity,
                    double radius, double mass, double restitution) {
  BodyDef def;
  def.name = name;
  def.position = position;
  def.velocity = velocity;
  def.mass = mass;
  def.shapes.push_back({Shape::circle(radius), restitution});
  return def;
}

/// A static ground: the segment from (−10, 0) to (10, 0) m.
inline BodyDef ground(double restitution) {
  BodyDef def;
  def.name = "ground";
  def.type = BodyType::Static;
  def.shapes.push_back({Shape::segment({-10.0, 0.0}, {10.0, 0.0}), restitution});
  return def;
}

/// A static open box: a floor from (−half_width, 0) to (half_width, 0) m and walls up to
/// `height` m at both ends, every side of friction `friction` and C_R 0.
inline BodyDef open_box(double half_width, double height, double friction) {
  BodyDef def;
  def.name = "box";
  def.type = BodyType::Static;
  for (const auto& [a, b] : {std::pair{Vec2(-half_width, 0.0), Vec2(half_width, 0.0)},
                             std::pair{Vec2(-half_width, 0.0), Vec2(-half_width, height)},
                             std::pair{Vec2(half_width, 0.0), Vec2(half_width, height)}}) {
    def.shapes.push_back({Shape::segment(a, b), 0.0, friction});
  }
  return def;
}

/// Uniform gravity of `g` [m/s²] downwards.
inline Settings with_gravity(double g) {
  Settings settings;
  settings.gravity = {0.0, -g};
  return settings;
}

/// The oracle's default options with `method`.
inline verification::OracleOptions with(verification::OracleMethod method) {
  verification::OracleOptions options;
  options.method = method;
  return options;
}

inline Scene scene_of(const Settings& settings, std::vector<BodyDef> bodies) {
  Scene scene{};
  scene.settings = settings;
  scene.bodies = std::move(bodies);
  return scene;
}

}  // namespace gp::test
