#include "verification/oracle/model/world.hpp"

#include <variant>

#include "gamephysics/models/dd/angular_displacement.hpp"
#include "verification/oracle/model/body_mass.hpp"
#include "verification/oracle/model/rotation.hpp"

namespace gp::oracle {

namespace {

/// The shape's outline in the centre-of-mass frame.
std::vector<Vec2> outline(const ShapeGeometry& geometry, const Vec2& center) {
  if (const auto* disc = std::get_if<Circle>(&geometry)) return {disc->center - center};
  if (const auto* segment = std::get_if<Segment>(&geometry)) {
    return {segment->a - center, segment->b - center};
  }
  const auto& polygon = std::get<ConvexPolygon>(geometry);
  std::vector<Vec2> vertices;
  for (int i = 0; i < polygon.count; ++i) vertices.push_back(polygon.vertices[i] - center);
  return vertices;
}

double radius_of(const ShapeGeometry& geometry) {
  if (const auto* disc = std::get_if<Circle>(&geometry)) return disc->radius;
  if (const auto* segment = std::get_if<Segment>(&geometry)) return segment->radius;
  return 0.0;
}

RigidBody rigid_body(const BodyDef& def) {
  const BodyMass mass = body_mass(def);
  const bool dynamic = def.type == BodyType::Dynamic;
  const bool moves = def.type != BodyType::Static;
  RigidBody body;
  body.name = def.name;
  body.type = def.type;
  body.mass = mass.mass;
  body.moment = mass.moment;
  body.inverse_mass = dynamic ? 1.0 / mass.mass : 0.0;
  body.inverse_moment = dynamic && mass.moment > 0.0 ? 1.0 / mass.moment : 0.0;
  body.initial = {def.position + rotated(mass.center, def.angle),
                  dd::rotated_orientation(def.angle, 0.0), moves ? def.velocity : Vec2::Zero(),
                  moves ? def.angular_velocity : 0.0};
  body.force = def.force;
  body.torque = def.torque;
  if (def.force_point) body.force_arm = *def.force_point - mass.center;
  for (const ShapeDef& shape : def.shapes) body.hulls.push_back(hull_of(shape, mass.center));
  return body;
}

}  // namespace

Hull hull_of(const ShapeDef& shape, const Vec2& center) {
  return {outline(shape.shape.geometry(), center), radius_of(shape.shape.geometry()),
          shape.restitution, shape.friction};
}

World build_world(const Scene& scene) {
  World world{{}, scene.settings.gravity, scene.settings.G};
  for (const BodyDef& def : scene.bodies) world.bodies.push_back(rigid_body(def));
  return world;
}

}  // namespace gp::oracle
