#include "verification/peers/chipmunk_world.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <variant>

#include "gamephysics/models/dd/angular_displacement.hpp"

namespace gp::peers {

namespace {

cpVect cp(const Vec2& v) {
  return cpv(v.x(), v.y());
}
Vec2 gp_vec(cpVect v) {
  return {v.x, v.y};
}

cpBody* make_body(const PeerBody& b) {
  switch (b.type) {
    case BodyType::Static:
      return cpBodyNewStatic();
    case BodyType::Kinematic:
      return cpBodyNewKinematic();
    case BodyType::Dynamic:
      break;
  }
  return cpBodyNew(b.mass, std::isfinite(b.moment) ? b.moment : INFINITY);
}

cpShape* make_shape(cpBody* body, const Shape& shape) {
  struct Make {
    cpBody* body;
    cpShape* operator()(const Circle& c) const {
      return cpCircleShapeNew(body, c.radius, cp(c.center));
    }
    cpShape* operator()(const ConvexPolygon& p) const {
      std::array<cpVect, kMaxPolygonVertices> vertices{};
      for (int i = 0; i < p.count; ++i) vertices[i] = cp(p.vertices[i]);
      return cpPolyShapeNewRaw(body, p.count, vertices.data(), 0.0);
    }
    cpShape* operator()(const Segment& s) const {
      return cpSegmentShapeNew(body, cp(s.a), cp(s.b), s.radius);
    }
  };
  return std::visit(Make{body}, shape.geometry());
}

/// Chipmunk computes an arbiter's elasticity and friction as products before this call on every
/// step of a contact; our engine combines surfaces as max and geometric mean.
cpBool combine_as_ours(cpArbiter* arbiter, cpSpace*, cpDataPointer) {
  cpShape* a = nullptr;
  cpShape* b = nullptr;
  cpArbiterGetShapes(arbiter, &a, &b);
  cpArbiterSetRestitution(arbiter, std::max(cpShapeGetElasticity(a), cpShapeGetElasticity(b)));
  cpArbiterSetFriction(arbiter, std::sqrt(cpShapeGetFriction(a) * cpShapeGetFriction(b)));
  return cpTrue;
}

}  // namespace

ChipmunkWorld::ChipmunkWorld(const PeerScene& scene)
    : PeerWorld(scene), space_(cpSpaceNew()), config_(scene.config) {
  cpSpaceSetGravity(space_, cp(scene.gravity));
  if (scene.velocity_iterations) cpSpaceSetIterations(space_, *scene.velocity_iterations);
  if (scene.config == PeerConfig::Matched) {
    cpSpaceSetCollisionSlop(space_, scene.linear_slop);
    cpSpaceAddDefaultCollisionHandler(space_)->preSolveFunc = combine_as_ours;
  }
  for (const PeerBody& b : scene.bodies) {
    cpBody* body = cpSpaceAddBody(space_, make_body(b));
    cpBodySetPosition(body, cp(b.start.position));
    cpBodySetAngle(body, b.start.angle);
    if (b.type != BodyType::Static) {
      cpBodySetVelocity(body, cp(b.start.velocity));
      cpBodySetAngularVelocity(body, b.start.angular_velocity);
    }
    for (const PeerShape& s : b.shapes) {
      cpShape* shape = cpSpaceAddShape(space_, make_shape(body, s.shape));
      cpShapeSetElasticity(shape, s.restitution);
      cpShapeSetFriction(shape, s.friction);
      shapes_.push_back(shape);
    }
    bodies_.push_back(body);
  }
}

ChipmunkWorld::~ChipmunkWorld() {
  // cpSpaceFree frees neither bodies nor shapes; they are freed after the space that refers to
  // them.
  cpSpaceFree(space_);
  for (cpShape* shape : shapes_) cpShapeFree(shape);
  for (cpBody* body : bodies_) cpBodyFree(body);
}

BodyState ChipmunkWorld::state(BodyId id) const {
  const cpBody* b = bodies_[id];
  return {gp_vec(cpBodyGetPosition(b)), dd::rotated_orientation(cpBodyGetAngle(b), 0.0),
          gp_vec(cpBodyGetVelocity(b)), cpBodyGetAngularVelocity(b)};
}

std::string ChipmunkWorld::describe() const {
  std::ostringstream text;
  text << "Chipmunk2D " << cpVersionString << ' ' << config_name(config_)
       << " (double, symplectic Euler, Debian build with debug checks on): "
       << cpSpaceGetIterations(space_) << " iterations, collision slop "
       << cpSpaceGetCollisionSlop(space_) << " m, collision bias "
       << cpSpaceGetCollisionBias(space_) << " (overlap left after 1 s), "
       << (config_ == PeerConfig::Matched ? "surfaces combined as ours by a pre-solve callback"
                                          : "surfaces combined as products (its own rule)")
       << ", sleeping " << (std::isinf(cpSpaceGetSleepTimeThreshold(space_)) ? "off" : "on");
  return text.str();
}

void ChipmunkWorld::advance(double dt) {
  cpSpaceStep(space_, dt);
}

void ChipmunkWorld::apply(BodyId id, const Wrench& wrench) {
  cpBodySetForce(bodies_[id], cp(wrench.force));
  cpBodySetTorque(bodies_[id], wrench.torque);
}

}  // namespace gp::peers
