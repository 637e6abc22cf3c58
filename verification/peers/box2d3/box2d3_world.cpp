#include "verification/peers/box2d3/box2d3_world.hpp"

// Box2D 3's headers: only this file of the project includes them (box2d3_world.hpp).
#include <box2d/box2d.h>
#include <box2d/constants.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <variant>

#include "gamephysics/models/dd/angular_displacement.hpp"
#include "scene/input_error.hpp"

namespace gp::peers {

// Positions in double (BOX2D_DOUBLE_PRECISION) would need their own conversions.
static_assert(std::is_same_v<b2Pos, b2Vec2>, "the Box2D 3 peer maps Box2D 3's float build");
static_assert(B2_MAX_POLYGON_VERTICES >= kMaxPolygonVertices, "our polygons fit Box2D 3's");

struct Box2d3World::Box2d {
  b2WorldDef def;  // what the world was made with, for describe()
  b2WorldId world;
  std::vector<b2BodyId> bodies;
};

namespace {

b2Vec2 b2(const Vec2& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}

Vec2 ours(const b2Vec2& v) {
  return {v.x, v.y};
}

// From our angle rather than b2MakeRot, whose cosine and sine are approximations.
b2Rot rotation(double angle) {
  return {static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))};
}

// The same mapping as Box2dWorld's, over Box2D 3's enum of the same name, which no file may see
// beside Box2D 2.4's.
b2BodyType b2_type(BodyType type) {
  switch (type) {
    case BodyType::Static:
      return b2_staticBody;
    case BodyType::Kinematic:
      return b2_kinematicBody;
    case BodyType::Dynamic:
      break;
  }
  return b2_dynamicBody;
}

std::string version() {
  const b2Version v = b2GetVersion();
  return std::to_string(v.major) + '.' + std::to_string(v.minor) + '.' + std::to_string(v.revision);
}

// Box2D 3 defines B2_ENABLE_ASSERT for its users in RelWithDebInfo, where its asserts stay on.
#if defined(NDEBUG) && !defined(B2_ENABLE_ASSERT)
constexpr std::string_view kAsserts = "asserts off";
#else
constexpr std::string_view kAsserts = "asserts on";
#endif

// Where the library came from and how it was built, for build() and describe().
std::string origin() {
  return "built from GP_BOX2D3_DIR, " + std::string(GP_BOX2D3_SIMD) + ", " + std::string(kAsserts);
}

/// Adds `surface` to `body`; false for a polygon that Box2D 3 cannot hull (vertices it welds,
/// within 4 linear slops of each other, or a polygon within a linear slop of a line).
bool add_shape(b2BodyId body, const PeerShape& surface) {
  b2ShapeDef def = b2DefaultShapeDef();
  def.density = 0.0f;          // the mass is set from ours, never from the shapes
  def.updateBodyMass = false;  // b2Body_SetMassData sets it once every shape is on
  def.material.friction = static_cast<float>(surface.friction);
  def.material.restitution = static_cast<float>(surface.restitution);
  const ShapeGeometry& geometry = surface.shape.geometry();
  if (const auto* c = std::get_if<Circle>(&geometry)) {
    const b2Circle circle{b2(c->center), static_cast<float>(c->radius)};
    b2CreateCircleShape(body, &def, &circle);
  } else if (const auto* p = std::get_if<ConvexPolygon>(&geometry)) {
    std::array<b2Vec2, kMaxPolygonVertices> points{};
    for (int i = 0; i < p->count; ++i) points[i] = b2(p->vertices[i]);
    const b2Hull hull = b2ComputeHull(points.data(), p->count);
    if (hull.count == 0) return false;
    const b2Polygon polygon = b2MakePolygon(&hull, 0.0f);  // radius 0: our outline, no skin
    b2CreatePolygonShape(body, &def, &polygon);
  } else if (const auto& s = std::get<Segment>(geometry); s.radius > 0.0) {
    const b2Capsule capsule{b2(s.a), b2(s.b), static_cast<float>(s.radius)};
    b2CreateCapsuleShape(body, &def, &capsule);
  } else {
    const b2Segment segment{b2(s.a), b2(s.b)};
    b2CreateSegmentShape(body, &def, &segment);
  }
  return true;
}

}  // namespace

Box2d3World::Box2d3World(const PeerScene& scene)
    : PeerWorld(scene), box2d_(std::make_unique<Box2d>()), config_(scene.config) {
  b2WorldDef& def = box2d_->def;
  def = b2DefaultWorldDef();
  def.gravity = b2(scene.gravity);
  def.enableSleep = config_ == PeerConfig::Default;
  if (config_ == PeerConfig::Matched) {
    def.restitutionThreshold = static_cast<float>(scene.restitution_threshold);
  }
  def.workerCount = 1;  // serial, as every engine of the bench's rows but ours-2-threads
  box2d_->world = b2CreateWorld(&def);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const PeerBody& b = scene.bodies[i];
    b2BodyDef body_def = b2DefaultBodyDef();
    body_def.type = b2_type(b.type);
    body_def.position = b2(b.start.position);
    body_def.rotation = rotation(b.start.angle);
    body_def.linearVelocity = b2(b.start.velocity);
    body_def.angularVelocity = static_cast<float>(b.start.angular_velocity);
    body_def.motionLocks.angularZ = b.type == BodyType::Dynamic && !std::isfinite(b.moment);
    const b2BodyId body = b2CreateBody(box2d_->world, &body_def);
    box2d_->bodies.push_back(body);
    for (std::size_t k = 0; k < b.shapes.size(); ++k) {
      if (!add_shape(body, b.shapes[k])) {
        throw InputError("bodies[" + std::to_string(i) + "].shapes[" + std::to_string(k) + "]",
                         "a polygon that Box2D 3 can hull",
                         "vertices welded or collinear within its linear slop");
      }
    }
    if (b.type == BodyType::Dynamic) {
      b2MassData mass{};
      mass.mass = static_cast<float>(b.mass);
      mass.center = b2Vec2{0.0f, 0.0f};
      mass.rotationalInertia = body_def.motionLocks.angularZ ? 0.0f : static_cast<float>(b.moment);
      b2Body_SetMassData(body, mass);
    }
  }
}

Box2d3World::~Box2d3World() {
  b2DestroyWorld(box2d_->world);
}

BodyState Box2d3World::state(BodyId id) const {
  const b2BodyId b = box2d_->bodies[id];
  const b2Rot q = b2Body_GetRotation(b);
  return {
      ours(b2Body_GetWorldCenter(b)),
      dd::rotated_orientation(std::atan2(static_cast<double>(q.s), static_cast<double>(q.c)), 0.0),
      ours(b2Body_GetLinearVelocity(b)), b2Body_GetAngularVelocity(b)};
}

std::string Box2d3World::describe() const {
  const b2WorldDef& def = box2d_->def;
  std::ostringstream text;
  text << "Box2D " << version() << ' ' << config_name(config_) << " (float, " << origin()
       << ", one worker): " << kSubSteps
       << " sub-steps of symplectic Euler, each with a relaxing pass (the scene's iterations do "
          "not map onto them), soft contacts of "
       << def.contactHertz << " Hz and damping ratio " << def.contactDampingRatio
       << " pushed apart at most " << def.contactSpeed << " m/s, speculative distance "
       << B2_SPECULATIVE_DISTANCE << " m, polygons without skin, restitution threshold "
       << b2World_GetRestitutionThreshold(box2d_->world) << " m/s, sleeping "
       << (b2World_IsSleepingEnabled(box2d_->world) ? "on" : "off");
  return text.str();
}

Box2d3Body Box2d3World::body(BodyId id) const {
  const b2BodyId b = box2d_->bodies[id];
  const b2MassData mass = b2Body_GetMassData(b);
  Box2d3Body read{mass.mass,
                  mass.rotationalInertia,
                  ours(b2Body_GetLocalCenter(b)),
                  ours(b2Body_GetPosition(b)),
                  {},
                  0.0};
  std::vector<b2ShapeId> shapes(static_cast<std::size_t>(b2Body_GetShapeCount(b)));
  b2Body_GetShapes(b, shapes.data(), static_cast<int>(shapes.size()));
  for (const b2ShapeId shape : shapes) {
    if (b2Shape_GetType(shape) != b2_polygonShape) continue;
    const b2Polygon p = b2Shape_GetPolygon(shape);
    for (int i = 0; i < p.count; ++i) {
      read.polygon_vertices.push_back(ours(b2Body_GetWorldPoint(b, p.vertices[i])));
    }
    read.polygon_radius = std::max(read.polygon_radius, static_cast<double>(p.radius));
  }
  return read;
}

std::string_view Box2d3World::build() {
  static const std::string text = "float, Box2D " + version() + ' ' + origin() + ", " +
                                  std::to_string(kSubSteps) + " sub-steps";
  return text;
}

void Box2d3World::advance(double dt) {
  b2World_Step(box2d_->world, static_cast<float>(dt), kSubSteps);
}

void Box2d3World::apply(BodyId id, const Wrench& wrench) {
  b2Body_ApplyForceToCenter(box2d_->bodies[id], b2(wrench.force), true);
  b2Body_ApplyTorque(box2d_->bodies[id], static_cast<float>(wrench.torque), true);
}

}  // namespace gp::peers
