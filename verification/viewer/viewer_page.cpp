#include "verification/viewer/viewer_page.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "engine/space_impl.hpp"
#include "gamephysics/models/dd/impulse.hpp"
#include "scene/settings.hpp"
#include "verification/html/html_escape.hpp"
#include "verification/viewer/viewer_assets.hpp"

namespace gp::verification {

namespace {

using nlohmann::json;

json vec(const Vec2& v) {
  return json::array({v.x(), v.y()});
}

// An infinite mass or moment (static, kinematic, non-rotating bodies) as JSON null.
json finite_or_null(double value) {
  return std::isfinite(value) ? json(value) : json(nullptr);
}

json shape_json(const Shape& shape) {
  return std::visit(
      [](const auto& g) -> json {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Circle>) {
          return {{"kind", "circle"}, {"center", vec(g.center)}, {"radius", g.radius}};
        } else if constexpr (std::is_same_v<G, ConvexPolygon>) {
          json vertices = json::array();
          for (int i = 0; i < g.count; ++i) vertices.push_back(vec(g.vertices[i]));
          return {{"kind", "polygon"}, {"vertices", vertices}};
        } else {
          return {{"kind", "segment"}, {"a", vec(g.a)}, {"b", vec(g.b)}, {"radius", g.radius}};
        }
      },
      shape.geometry());
}

const char* type_name(BodyType type) {
  switch (type) {
    case BodyType::Static:
      return "static";
    case BodyType::Kinematic:
      return "kinematic";
    default:
      return "dynamic";
  }
}

// Each body with its constant applied force and torque, as the scene gives them (bodies are
// numbered in the scene's order), for the page's closed forms.
json bodies_json(const Space& space, const Scene& scene) {
  json bodies = json::array();
  for (BodyId id = 0; id < space.body_count(); ++id) {
    const BodyDef& def = scene.bodies.at(id);
    bodies.push_back({{"name", std::string(space.name(id))},
                      {"type", type_name(space.type(id))},
                      {"mass", finite_or_null(space.mass(id))},
                      {"moment", finite_or_null(space.moment(id))},
                      {"force", vec(def.force)},
                      {"force_at_com", !def.force_point.has_value()},
                      {"torque", def.torque},
                      {"shapes", json::array()}});
  }
  // The shapes in their body's frame centred on the centre of mass, as the engine holds them.
  const BodyShapes& shapes = SpaceInternals::context(space).shapes;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    json shape = shape_json(Shape::copy_of(shapes[i].local));
    shape["restitution"] = shapes[i].restitution;
    shape["friction"] = shapes[i].friction;
    bodies[shapes[i].body]["shapes"].push_back(shape);
  }
  return bodies;
}

// Per frame: each body's state [x, y, ϕ, vx, vy, ω] and quantities [KE_trans, KE_rot, PE, px, py,
// L], the totals [KE_trans, KE_rot, PE, px, py, L] and the contacts [a, b, x, y, nx, ny, impulse].
json frames_json(const Recording& recording) {
  json times = json::array(), states = json::array(), quantities = json::array(),
       totals = json::array(), contacts = json::array();
  for (const Frame& f : recording.frames) {
    times.push_back(f.time);
    json s = json::array(), q = json::array(), c = json::array();
    for (const BodyState& b : f.states) {
      s.push_back({b.position.x(), b.position.y(), b.angle, b.velocity.x(), b.velocity.y(),
                   b.angular_velocity});
    }
    for (const BodyQuantities& b : f.quantities) {
      q.push_back({b.translational_energy, b.rotational_energy, b.potential_energy, b.momentum.x(),
                   b.momentum.y(), b.angular_momentum});
    }
    for (const ContactPoint& p : f.contacts) {
      c.push_back(
          {p.body_a, p.body_b, p.point.x(), p.point.y(), p.normal.x(), p.normal.y(), p.impulse});
    }
    const Invariants& t = f.totals;
    totals.push_back({t.translational_energy, t.rotational_energy, t.potential_energy,
                      t.momentum.x(), t.momentum.y(), t.angular_momentum});
    states.push_back(std::move(s));
    quantities.push_back(std::move(q));
    contacts.push_back(std::move(c));
  }
  return {{"t", times},
          {"states", states},
          {"quantities", quantities},
          {"totals", totals},
          {"contacts", contacts}};
}

// Each impact with the velocity changes its impulse J = j n causes (DD:impulseV: Δv = J / m; B
// takes the reaction −J).
json impacts_json(const Space& space, const Recording& recording) {
  json impacts = json::array();
  for (const Impact& i : recording.impacts) {
    const Vec2 J = i.impulse * i.normal;
    const double inverse_a = 1.0 / space.mass(i.body_a), inverse_b = 1.0 / space.mass(i.body_b);
    impacts.push_back({{"t", i.time},
                       {"a", i.body_a},
                       {"b", i.body_b},
                       {"normal", vec(i.normal)},
                       {"point", vec(i.point)},
                       {"j", i.impulse},
                       {"dv_a", vec(dd::velocity_change_from_impulse(J, inverse_a))},
                       {"dv_b", vec(dd::velocity_change_from_impulse(-J, inverse_b))}});
  }
  return impacts;
}

json oracle_json(const ViewerRun& run) {
  if (!run.oracle) return nullptr;
  json states = json::array();
  for (const auto& frame : run.oracle->states) {
    json s = json::array();
    for (const BodyState& b : frame) s.push_back({b.position.x(), b.position.y(), b.angle});
    states.push_back(std::move(s));
  }
  return {{"method", run.oracle_method}, {"states", states}};
}

// The data as a script element's text: "</" would end the element early.
std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) {
    text.replace(at, 2, "<\\/");
  }
  return text;
}

// The template with each marker replaced by its value, in one pass over the template, so that a
// value (a body's name, say) can never be taken for a marker.
std::string fill(std::string_view page,
                 const std::vector<std::pair<std::string_view, std::string>>& values) {
  std::string out;
  std::size_t done = 0;
  while (true) {
    std::size_t next = std::string_view::npos;
    const std::pair<std::string_view, std::string>* found = nullptr;
    for (const auto& v : values) {
      const auto at = page.find(v.first, done);
      if (at < next) next = at, found = &v;
    }
    if (!found) break;
    out.append(page.substr(done, next - done)).append(found->second);
    done = next + found->first.size();
  }
  return out.append(page.substr(done));
}

}  // namespace

void write_viewer_page(std::ostream& out, const ViewerRun& run) {
  const Settings& settings = run.space.settings();
  const json data = {
      {"title", run.title},
      {"description", run.description},
      {"integrator", std::string(integrator_name(settings.integrator))},
      {"dt", run.scene.dt},
      {"duration", run.scene.duration},
      {"output_dt", run.scene.output_dt},
      {"gravity", vec(settings.gravity)},
      {"G", settings.G ? json(*settings.G) : json(nullptr)},
      {"bodies", bodies_json(run.space, run.scene)},
      {"frames", frames_json(run.recording)},
      {"impacts", impacts_json(run.space, run.recording)},
      {"oracle", oracle_json(run)},
      {"audit", run.audit_page},
  };
  const std::string page = fill(
      viewer_assets::kHtml, {{"GP_TITLE", html_escape(run.title)},
                             {"/*GP_CSS*/", std::string(viewer_assets::kCss)},
                             {"/*GP_DATA*/", script_safe(data.dump())},
                             {"/*GP_CLOSED_FORM_JS*/", std::string(viewer_assets::kClosedFormJs)},
                             {"/*GP_JS*/", std::string(viewer_assets::kJs)}});
  out << page;
}

}  // namespace gp::verification
