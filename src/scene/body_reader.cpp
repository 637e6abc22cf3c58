#include "scene/body_reader.hpp"

#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

#include "scene/input_error.hpp"
#include "scene/json_fields.hpp"

namespace gp {

namespace {

constexpr std::array<std::pair<std::string_view, BodyType>, 3> kBodyTypes{{
    {"dynamic", BodyType::Dynamic},
    {"static", BodyType::Static},
    {"kinematic", BodyType::Kinematic},
}};

// Fields that only a dynamic body uses: static and kinematic bodies have infinite mass and are
// not moved by forces, so giving one of these is a mistake rather than something to ignore.
constexpr std::array<std::string_view, 5> kDynamicOnly{"mass", "moment", "force", "force_point",
                                                       "torque"};
// A static body never moves.
constexpr std::array<std::string_view, 2> kMovingOnly{"velocity", "angular_velocity"};

BodyType read_body_type(const JsonObject& body) {
  const auto name = body.get_or<std::string>("type", "dynamic");
  for (const auto& [n, type] : kBodyTypes) {
    if (n == name) return type;
  }
  throw InputError(body.path("type"), "must be one of dynamic, static, kinematic",
                   describe(nlohmann::json(name)));
}

/// CSV rows carry the name unquoted (trajectory output), so it must not need quoting.
std::string read_name(const JsonObject& body) {
  auto name = body.get<std::string>("name");
  if (name.empty() || name.find_first_of(",\"\r\n") != std::string::npos) {
    throw InputError(body.path("name"),
                     "must be non-empty, without commas, quotes or line breaks (a CSV field)",
                     describe(nlohmann::json(name)));
  }
  return name;
}

void reject_unused(const JsonObject& body, BodyType type) {
  if (type == BodyType::Dynamic) return;
  const std::string kind = type == BodyType::Static ? "static" : "kinematic";
  for (std::string_view field : kDynamicOnly) {
    if (const nlohmann::json* value = body.find(field)) {
      const std::string rule = "has no effect on a " + kind +
                               " body (only dynamic bodies have mass and respond to forces)";
      throw InputError(body.path(field), rule, describe(*value));
    }
  }
  if (type != BodyType::Static) return;
  for (std::string_view field : kMovingOnly) {
    if (const nlohmann::json* value = body.find(field)) {
      throw InputError(body.path(field), "has no effect on a static body (it never moves)",
                       describe(*value));
    }
  }
}

std::vector<Vec2> read_vertices(const JsonObject& shape) {
  const nlohmann::json& list = read_array(shape.required("vertices"), shape.path("vertices"));
  std::vector<Vec2> vertices;
  for (std::size_t i = 0; i < list.size(); ++i) {
    vertices.push_back(read<Vec2>(list[i], element_path(shape.path("vertices"), i)));
  }
  return vertices;
}

/// The geometry of `shape` from the fields of its type (each type also allows the surface
/// properties and the density every shape may carry); the Shape factories check it. Fields are
/// read one statement at a time so that the first missing one reported is always the same.
Shape read_geometry(const JsonObject& shape, const std::string& type) {
  if (type == "circle") {
    shape.allow_only({"type", "radius", "center", "restitution", "friction", "density"});
    const auto radius = shape.get<double>("radius");
    return Shape::circle(radius, shape.get_or<Vec2>("center", Vec2::Zero()));
  }
  if (type == "box") {
    shape.allow_only({"type", "width", "height", "center", "restitution", "friction", "density"});
    const auto width = shape.get<double>("width");
    const auto height = shape.get<double>("height");
    return Shape::box(width, height, shape.get_or<Vec2>("center", Vec2::Zero()));
  }
  if (type == "polygon") {
    shape.allow_only({"type", "vertices", "restitution", "friction", "density"});
    return Shape::polygon(read_vertices(shape));
  }
  if (type == "segment") {
    shape.allow_only({"type", "a", "b", "radius", "restitution", "friction", "density"});
    const auto a = shape.get<Vec2>("a");
    const auto b = shape.get<Vec2>("b");
    return Shape::segment(a, b, shape.get_or<double>("radius", 0.0));
  }
  throw InputError(shape.path("type"), "must be one of circle, box, polygon, segment",
                   describe(nlohmann::json(type)));
}

/// read_geometry, with the factories' std::invalid_argument turned into an InputError naming the
/// shape's path.
Shape read_checked_geometry(const JsonObject& shape, const nlohmann::json& value,
                            const std::string& path) {
  try {
    return read_geometry(shape, shape.get<std::string>("type"));
  } catch (const std::invalid_argument& e) {
    // The factories say "<rule>, got <value>", or only the rule when the value is the shape.
    const std::string message = e.what();
    const std::string got = ", got ";
    const std::size_t at = message.rfind(got);
    if (at == std::string::npos) throw InputError(path, message, describe(value));
    throw InputError(path, message.substr(0, at), message.substr(at + got.size()));
  }
}

ShapeDef read_shape(const nlohmann::json& value, const std::string& path) {
  const JsonObject shape(value, path);
  ShapeDef def{read_checked_geometry(shape, value, path)};
  def.restitution = shape.get_or<double>("restitution", def.restitution);
  def.friction = shape.get_or<double>("friction", def.friction);
  def.density = shape.get_or<double>("density", def.density);
  return def;
}

}  // namespace

BodyDef read_body(const nlohmann::json& value, const std::string& path) {
  const JsonObject body(value, path);
  body.allow_only({"name", "type", "position", "angle", "velocity", "angular_velocity", "mass",
                   "moment", "force", "force_point", "torque", "shapes"});
  BodyDef def;
  def.name = read_name(body);
  def.type = read_body_type(body);
  reject_unused(body, def.type);
  def.position = body.get<Vec2>("position");
  def.angle = body.get_or<double>("angle", def.angle);
  def.velocity = body.get_or<Vec2>("velocity", def.velocity);
  def.angular_velocity = body.get_or<double>("angular_velocity", def.angular_velocity);
  def.mass = body.get_optional<double>("mass");
  def.moment = body.get_optional<double>("moment");
  def.force = body.get_or<Vec2>("force", def.force);
  def.force_point = body.get_optional<Vec2>("force_point");
  def.torque = body.get_or<double>("torque", def.torque);
  if (const nlohmann::json* value = body.find("shapes")) {
    const std::string shapes_path = body.path("shapes");
    const nlohmann::json& shapes = read_array(*value, shapes_path);
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      def.shapes.push_back(read_shape(shapes[k], element_path(shapes_path, k)));
    }
  }
  return def;
}

}  // namespace gp
