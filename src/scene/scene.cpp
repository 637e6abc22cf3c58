#include "scene/scene.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "scene/body_reader.hpp"
#include "scene/input_error.hpp"
#include "scene/json_document.hpp"
#include "scene/json_fields.hpp"
#include "scene/validation.hpp"

namespace gp {

namespace {

// Most steps (duration / dt) and output intervals (duration / output_dt) of a run: a run must end,
// and run_scene's step arithmetic stays exact far beyond this.
constexpr double kMaxRunSteps = 1e9;

std::string read_text(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    throw InputError("(file)", "must be an existing regular file",
                     std::filesystem::exists(file, error) ? "not a regular file" : "no such file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in.is_open()) throw InputError("(file)", "must be readable", std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void apply(const SceneOverrides& overrides, nlohmann::json& document) {
  if (!document.is_object()) return;  // reported when the document is read
  if (overrides.integrator) document["integrator"] = *overrides.integrator;
  if (overrides.dt) document["dt"] = *overrides.dt;
  if (overrides.duration) document["duration"] = *overrides.duration;
  if (overrides.output_dt) document["output_dt"] = *overrides.output_dt;
}

/// `field` from the root's `key`, left as it is when the key is left out.
template <typename T>
void read_setting(const JsonObject& root, const char* key, T& field) {
  field = root.get_or<T>(key, field);
}

Settings read_settings(const JsonObject& root) {
  Settings settings;
  read_setting(root, "gravity", settings.gravity);
  settings.G = root.get_optional<double>("G");
  if (const auto name = root.get_optional<std::string>("integrator")) {
    const auto kind = integrator_from_name(*name);
    if (!kind) {
      throw InputError("integrator", "must be one of symplectic_euler, velocity_verlet, rk4",
                       describe(nlohmann::json(*name)));
    }
    settings.integrator = *kind;
  }
  read_setting(root, "velocity_iterations", settings.velocity_iterations);
  read_setting(root, "position_iterations", settings.position_iterations);
  read_setting(root, "velocity_tolerance", settings.velocity_tolerance);
  read_setting(root, "direct_solve_points", settings.direct_solve_points);
  read_setting(root, "direct_solve_uneven_points", settings.direct_solve_uneven_points);
  read_setting(root, "direct_solve_mass_ratio", settings.direct_solve_mass_ratio);
  read_setting(root, "direct_solve_resting_points", settings.direct_solve_resting_points);
  read_setting(root, "restitution_threshold", settings.restitution_threshold);
  read_setting(root, "sleep", settings.sleep);
  read_setting(root, "sleep_speed", settings.sleep_speed);
  read_setting(root, "sleep_angular_speed", settings.sleep_angular_speed);
  read_setting(root, "time_to_sleep", settings.time_to_sleep);
  read_setting(root, "coloured_island_contacts", settings.coloured_island_contacts);
  read_setting(root, "island_part_contacts", settings.island_part_contacts);
  read_setting(root, "island_parts", settings.island_parts);
  validate_settings(settings);
  return settings;
}

/// dt, duration and output_dt, and a bounded number of steps.
void read_timing(const JsonObject& root, Scene& scene) {
  scene.dt = root.get<double>("dt");
  validate_step(scene.dt, "dt");
  scene.duration = root.get<double>("duration");
  if (!std::isfinite(scene.duration) || scene.duration < 0.0) {
    throw InputError("duration", "must be a finite number >= 0", describe(scene.duration));
  }
  scene.output_dt = root.get_or<double>("output_dt", scene.dt);
  validate_step(scene.output_dt, "output_dt");
  if (scene.duration / scene.dt > kMaxRunSteps) {
    throw InputError("duration", "must be at most 1e9 time steps (duration / dt)",
                     describe(scene.duration));
  }
  if (scene.duration / scene.output_dt > kMaxRunSteps) {
    throw InputError("duration", "must be at most 1e9 output intervals (duration / output_dt)",
                     describe(scene.duration));
  }
}

std::vector<BodyDef> read_bodies(const JsonObject& root) {
  const nlohmann::json& list = read_array(root.required("bodies"), "bodies");
  std::vector<BodyDef> bodies;
  std::map<std::string, std::size_t> index_of_name;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = element_path("bodies", i);
    bodies.push_back(read_body(list[i], path));
    // Names label the trajectory's rows: two bodies with one name could not be told apart.
    const auto [first, inserted] = index_of_name.emplace(bodies.back().name, i);
    if (!inserted) {
      throw InputError(
          path + ".name",
          "must be unique (also the name of " + element_path("bodies", first->second) + ")",
          describe(nlohmann::json(bodies.back().name)));
    }
  }
  return bodies;
}

}  // namespace

Scene load_scene(const std::filesystem::path& file, const SceneOverrides& overrides) {
  return parse_scene(read_text(file), overrides);
}

Scene parse_scene(const std::string& text, const SceneOverrides& overrides) {
  nlohmann::json document = parse_json_document(text);
  apply(overrides, document);
  const JsonObject root(document, "");
  root.allow_only({"description",
                   "gravity",
                   "G",
                   "integrator",
                   "dt",
                   "duration",
                   "output_dt",
                   "velocity_iterations",
                   "velocity_tolerance",
                   "direct_solve_points",
                   "direct_solve_uneven_points",
                   "direct_solve_mass_ratio",
                   "direct_solve_resting_points",
                   "position_iterations",
                   "restitution_threshold",
                   "sleep",
                   "sleep_speed",
                   "sleep_angular_speed",
                   "time_to_sleep",
                   "coloured_island_contacts",
                   "island_part_contacts",
                   "island_parts",
                   "bodies"});
  root.get_optional<std::string>("description");  // for the reader of the file: type only
  Scene scene;
  scene.settings = read_settings(root);
  read_timing(root, scene);
  scene.bodies = read_bodies(root);
  return scene;
}

}  // namespace gp
