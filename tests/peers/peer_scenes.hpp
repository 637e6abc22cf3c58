#pragma once
// Small scenes for the peer-engine tests, built in code.

#include "scene/scene.hpp"

namespace gp::peers::testing {

/// A scene with no bodies yet: no gravity, dt [s], duration 1 s, output every 0.5 s.
inline Scene empty_scene(double dt) {
  Scene scene;
  scene.dt = dt;
  scene.duration = 1.0;
  scene.output_dt = 0.5;
  return scene;
}

/// A dynamic disc of radius 0.5 m and mass [kg] at `position` [m] with `velocity` [m/s].
inline BodyDef ball(const std::string& name, const Vec2& position, const Vec2& velocity,
                    double mass, double restitution) {
  BodyDef def;
  def.name = name;
  def.position = position;
  def.velocity = velocity;
  def.mass = mass;
  def.shapes.push_back({Shape::circle(0.5), restitution});
  return def;
}

/// A dynamic box `width` × `height` [m] of density 1 kg/m² at `position` [m], friction μ [1].
inline BodyDef box_body(const std::string& name, double width, double height, const Vec2& position,
                        double friction) {
  BodyDef def;
  def.name = name;
  def.position = position;
  def.shapes.push_back({Shape::box(width, height), 0.0, friction});
  return def;
}

/// A static floor `width` [m] wide and 1 m thick whose top is y = 0, with friction μ [1].
inline BodyDef floor_box(double width, double friction) {
  BodyDef def;
  def.name = "floor";
  def.type = BodyType::Static;
  def.shapes.push_back({Shape::box(width, 1.0, {0.0, -0.5}), 0.0, friction});
  return def;
}

}  // namespace gp::peers::testing
