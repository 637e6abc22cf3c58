#pragma once
// Small scenes for the peer-engine tests, built in code.

#include <memory>

#include "scene/scene.hpp"
#include "verification/peers/peer_world.hpp"

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

/// The free flight of the peers' motion tests: a point mass of 1 kg thrown from x0 [m] at v0 [m/s]
/// under gravity g [m/s²], stepped `steps` times by h [s].
namespace projectile {
inline constexpr double h = 0.01;
inline constexpr int steps = 200;
inline const Vec2 x0{1.5, 2.0}, v0{10.0, 10.0}, g{0.0, -9.81};
}  // namespace projectile

/// The projectile in `engine`, after its steps.
inline std::unique_ptr<PeerWorld> thrown_projectile(PeerEngine engine) {
  Scene scene = empty_scene(projectile::h);
  scene.settings.gravity = projectile::g;
  BodyDef body;
  body.name = "projectile";
  body.position = projectile::x0;
  body.velocity = projectile::v0;
  body.mass = 1.0;
  scene.bodies.push_back(body);
  auto world = make_peer(engine, peer_scene(scene));
  for (int n = 0; n < projectile::steps; ++n) world->step(projectile::h);
  return world;
}

}  // namespace gp::peers::testing
