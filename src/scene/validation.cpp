#include "scene/validation.hpp"

#include <bit>
#include <cmath>
#include <numbers>
#include <sstream>

#include "scene/input_error.hpp"

namespace gp {

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";  // the sign of a NaN depends on how it was made
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

std::string number_text(const Vec2& v) {
  return "[" + number_text(v.x()) + ", " + number_text(v.y()) + "]";
}

namespace {

void positive(double value, const std::string& field, const std::string& why) {
  validate_finite(value, field);
  if (!(value > 0.0)) throw InputError(field, "must be > 0 (" + why + ")", number_text(value));
}

void non_negative(double value, const std::string& field) {
  validate_finite(value, field);
  if (!(value >= 0.0)) throw InputError(field, "must be >= 0", number_text(value));
}

void count_up_to(int value, int most, const std::string& field) {
  if (value < 0 || value > most) {
    throw InputError(field, "must be in [0, " + std::to_string(most) + "]", number_text(value));
  }
}

// Iterations of the contact solver per step at most: a step's work grows with them, and 1000 is
// a hundred times the default.
constexpr int kMaxIterations = 1000;
// Points of an island solved directly at most: a round of the solve costs a sparse factorisation,
// about 0.3 ms for a pyramid of 292 points (callgrind), and grows faster than their number.
constexpr int kMaxDirectSolvePoints = 1024;
// Points of a resting island solved directly at most: solved once, not at every step, such an
// island may be larger; 29,900 points (a 100-row pyramid) take 0.7 s, and 65,536 a few seconds.
constexpr int kMaxRestingSolvePoints = 65536;

}  // namespace

void validate_finite(double value, const std::string& field) {
  if (!std::isfinite(value)) throw InputError(field, "must be a finite number", number_text(value));
}

void validate_finite(const Vec2& value, const std::string& field) {
  if (!value.allFinite()) throw InputError(field, "must be finite numbers", number_text(value));
}

void validate_body(const BodyDef& def, const std::string& prefix) {
  validate_finite(def.position, prefix + ".position");
  validate_finite(def.angle, prefix + ".angle");
  constexpr double two_pi = 2.0 * std::numbers::pi;
  if (def.angle < 0.0 || def.angle > two_pi) {
    throw InputError(prefix + ".angle", "must be in [0, 2π] (SRS software constraint on ϕ)",
                     number_text(def.angle));
  }
  validate_finite(def.velocity, prefix + ".velocity");
  validate_finite(def.angular_velocity, prefix + ".angular_velocity");
  validate_finite(def.force, prefix + ".force");
  validate_finite(def.torque, prefix + ".torque");
  if (def.force_point) validate_finite(*def.force_point, prefix + ".force_point");
  if (def.mass) positive(*def.mass, prefix + ".mass", "SRS data constraint m > 0");
  if (def.moment) positive(*def.moment, prefix + ".moment", "SRS data constraint I > 0");
  for (std::size_t k = 0; k < def.shapes.size(); ++k) {
    const ShapeDef& s = def.shapes[k];
    const std::string field = prefix + ".shapes[" + std::to_string(k) + "]";
    validate_finite(s.restitution, field + ".restitution");
    if (s.restitution < 0.0 || s.restitution > 1.0) {
      throw InputError(field + ".restitution", "must be in [0, 1] (SRS data constraint on C_R)",
                       number_text(s.restitution));
    }
    validate_finite(s.friction, field + ".friction");
    if (s.friction < 0.0)
      throw InputError(field + ".friction", "must be >= 0", number_text(s.friction));
    positive(s.density, field + ".density", "mass per unit area");
  }
  const bool has_area = [&] {
    for (const auto& s : def.shapes) {
      if (s.shape.kind() != ShapeKind::kSegment || std::get<Segment>(s.shape.geometry()).radius > 0)
        return true;
    }
    return false;
  }();
  if (def.type == BodyType::Dynamic && !def.mass && !has_area) {
    throw InputError(prefix + ".mass", "is required for a dynamic body without area", "none");
  }
}

void validate_settings(const Settings& settings) {
  validate_finite(settings.gravity, "gravity");
  if (settings.G) {
    validate_finite(*settings.G, "G");
    if (*settings.G < 0.0) throw InputError("G", "must be >= 0", number_text(*settings.G));
  }
  count_up_to(settings.velocity_iterations, kMaxIterations, "velocity_iterations");
  count_up_to(settings.position_iterations, kMaxIterations, "position_iterations");
  count_up_to(settings.direct_solve_points, kMaxDirectSolvePoints, "direct_solve_points");
  count_up_to(settings.direct_solve_uneven_points, kMaxDirectSolvePoints,
              "direct_solve_uneven_points");
  count_up_to(settings.direct_solve_resting_points, kMaxRestingSolvePoints,
              "direct_solve_resting_points");
  validate_finite(settings.direct_solve_mass_ratio, "direct_solve_mass_ratio");
  if (settings.direct_solve_mass_ratio < 1.0) {
    throw InputError("direct_solve_mass_ratio", "must be >= 1 (heaviest over lightest)",
                     number_text(settings.direct_solve_mass_ratio));
  }
  non_negative(settings.velocity_tolerance, "velocity_tolerance");
  non_negative(settings.restitution_threshold, "restitution_threshold");
  non_negative(settings.linear_slop, "linear_slop");
  non_negative(settings.contact_margin, "contact_margin");
  non_negative(settings.sleep_speed, "sleep_speed");
  non_negative(settings.sleep_angular_speed, "sleep_angular_speed");
  non_negative(settings.time_to_sleep, "time_to_sleep");
  if (settings.max_impacts_per_step < 0) {
    throw InputError("max_impacts_per_step", "must be >= 0",
                     number_text(settings.max_impacts_per_step));
  }
  if (settings.coloured_island_contacts < 0) {
    throw InputError("coloured_island_contacts", "must be >= 0 (0: never)",
                     number_text(settings.coloured_island_contacts));
  }
  if (settings.island_part_contacts < 0) {
    throw InputError("island_part_contacts", "must be >= 0 (0: never)",
                     number_text(settings.island_part_contacts));
  }
  if (settings.island_parts < 2 || settings.island_parts > Settings::kMaxIslandParts ||
      !std::has_single_bit(static_cast<unsigned>(settings.island_parts))) {
    throw InputError(
        "island_parts",
        "must be a power of two from 2 to " + std::to_string(Settings::kMaxIslandParts),
        number_text(settings.island_parts));
  }
}

void validate_step(double dt, const std::string& field) {
  positive(dt, field, "a time step");
}

}  // namespace gp
