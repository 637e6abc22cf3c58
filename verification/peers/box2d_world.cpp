#include "verification/peers/box2d_world.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <variant>

#include "gamephysics/models/dd/angular_displacement.hpp"

namespace gp::peers {

namespace {

b2Vec2 b2(const Vec2& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}

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

/// `p` with every edge moved inwards by `skin` [m], so that Box2D's rounding by the skin gives
/// back p's outline; none when p is too thin for that (an edge would turn round, or shrink to
/// under b2_linearSlop, where b2PolygonShape::Set welds its ends and fails on a 2-skin card).
std::optional<std::array<b2Vec2, kMaxPolygonVertices>> inset(const ConvexPolygon& p, double skin) {
  std::array<Vec2, kMaxPolygonVertices> moved{};
  for (int i = 0; i < p.count; ++i) {
    // Vertex i is where the lines of edges i − 1 and i, each moved by the skin, meet:
    // n_k · x = n_k · v_k − skin for k = i − 1, i.
    const int previous = (i + p.count - 1) % p.count;
    const Vec2& n0 = p.normals[previous];
    const Vec2& n1 = p.normals[i];
    const double d0 = n0.dot(p.vertices[previous]) - skin;
    const double d1 = n1.dot(p.vertices[i]) - skin;
    const double det = cross(n0, n1);
    moved[i] = Vec2(d0 * n1.y() - d1 * n0.y(), n0.x() * d1 - n1.x() * d0) / det;
  }
  std::array<b2Vec2, kMaxPolygonVertices> vertices{};
  for (int i = 0; i < p.count; ++i) {
    const int next = (i + 1) % p.count;
    const Vec2 edge = moved[next] - moved[i];
    if (edge.dot(p.vertices[next] - p.vertices[i]) <= 0.0 || edge.norm() < b2_linearSlop) {
      return std::nullopt;
    }
    vertices[i] = b2(moved[i]);
  }
  return vertices;
}

void add_fixture(b2Body* body, const b2Shape& shape, const PeerShape& surface, float threshold) {
  b2FixtureDef def;
  def.shape = &shape;
  def.density = 0.0f;  // the mass is set from ours, never from the fixtures
  def.friction = static_cast<float>(surface.friction);
  def.restitution = static_cast<float>(surface.restitution);
  def.restitutionThreshold = threshold;
  body->CreateFixture(&def);
}

void add_shape(b2Body* body, const PeerShape& surface, float threshold) {
  const ShapeGeometry& geometry = surface.shape.geometry();
  if (const auto* c = std::get_if<Circle>(&geometry)) {
    b2CircleShape circle;
    circle.m_p = b2(c->center);
    circle.m_radius = static_cast<float>(c->radius);
    add_fixture(body, circle, surface, threshold);
  } else if (const auto* p = std::get_if<ConvexPolygon>(&geometry)) {
    // A polygon thinner than two skins keeps its own vertices, and so grows by the skin.
    std::array<b2Vec2, kMaxPolygonVertices> vertices{};
    for (int i = 0; i < p->count; ++i) vertices[i] = b2(p->vertices[i]);
    vertices = inset(*p, b2_polygonRadius).value_or(vertices);
    b2PolygonShape polygon;
    polygon.Set(vertices.data(), p->count);
    add_fixture(body, polygon, surface, threshold);
  } else {
    const auto& s = std::get<Segment>(geometry);
    if (s.radius <= b2_polygonRadius) {
      b2EdgeShape edge;
      edge.SetTwoSided(b2(s.a), b2(s.b));
      add_fixture(body, edge, surface, threshold);
      return;
    }
    const Vec2 axis = s.b - s.a;
    b2PolygonShape core;
    core.SetAsBox(static_cast<float>(axis.norm() / 2),
                  static_cast<float>(s.radius - b2_polygonRadius), b2((s.a + s.b) / 2),
                  static_cast<float>(std::atan2(axis.y(), axis.x())));
    add_fixture(body, core, surface, threshold);
    for (const Vec2& end : {s.a, s.b}) {
      b2CircleShape cap;
      cap.m_p = b2(end);
      cap.m_radius = static_cast<float>(s.radius);
      add_fixture(body, cap, surface, threshold);
    }
  }
}

}  // namespace

Box2dWorld::Box2dWorld(const PeerScene& scene)
    : PeerWorld(scene),
      world_(std::make_unique<b2World>(b2(scene.gravity))),
      velocity_iterations_(scene.velocity_iterations.value_or(kDefaultVelocityIterations)),
      position_iterations_(scene.position_iterations.value_or(kDefaultPositionIterations)),
      restitution_threshold_(scene.config == PeerConfig::Matched
                                 ? static_cast<float>(scene.restitution_threshold)
                                 : b2FixtureDef().restitutionThreshold),
      config_(scene.config) {
  world_->SetAllowSleeping(config_ == PeerConfig::Default);
  for (const PeerBody& b : scene.bodies) {
    b2BodyDef def;
    def.type = b2_type(b.type);
    def.position = b2(b.start.position);
    def.angle = static_cast<float>(b.start.angle);
    def.linearVelocity = b2(b.start.velocity);
    def.angularVelocity = static_cast<float>(b.start.angular_velocity);
    def.fixedRotation = b.type == BodyType::Dynamic && !std::isfinite(b.moment);
    b2Body* body = world_->CreateBody(&def);
    for (const PeerShape& s : b.shapes) add_shape(body, s, restitution_threshold_);
    if (b.type == BodyType::Dynamic) {
      b2MassData mass;
      mass.mass = static_cast<float>(b.mass);
      mass.center = b2Vec2(0.0f, 0.0f);
      mass.I = def.fixedRotation ? 0.0f : static_cast<float>(b.moment);
      body->SetMassData(&mass);
    }
    bodies_.push_back(body);
  }
}

BodyState Box2dWorld::state(BodyId id) const {
  const b2Body* b = bodies_[id];
  const b2Vec2 p = b->GetWorldCenter();
  const b2Vec2 v = b->GetLinearVelocity();
  return {
      {p.x, p.y}, dd::rotated_orientation(b->GetAngle(), 0.0), {v.x, v.y}, b->GetAngularVelocity()};
}

std::string Box2dWorld::describe() const {
  std::ostringstream text;
  text << "Box2D " << b2_version.major << '.' << b2_version.minor << '.' << b2_version.revision
       << ' ' << config_name(config_)
       << " (float, symplectic Euler, Debian build with its asserts on): " << velocity_iterations_
       << " velocity and " << position_iterations_ << " position iterations, linear slop "
       << b2_linearSlop << " m, polygon skin " << b2_polygonRadius << " m, restitution threshold "
       << restitution_threshold_ << " m/s, sleeping "
       << (world_->GetAllowSleeping() ? "on" : "off");
  return text.str();
}

void Box2dWorld::advance(double dt) {
  world_->Step(static_cast<float>(dt), velocity_iterations_, position_iterations_);
}

void Box2dWorld::apply(BodyId id, const Wrench& wrench) {
  bodies_[id]->ApplyForceToCenter(b2(wrench.force), true);
  bodies_[id]->ApplyTorque(static_cast<float>(wrench.torque), true);
}

}  // namespace gp::peers
