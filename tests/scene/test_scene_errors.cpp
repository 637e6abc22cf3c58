// Every kind of bad scene file gives an InputError naming the JSON path of the fault, the rule
// and the offending value (FR:Verify-Physical_Constraints).
#include <catch2/catch.hpp>
#include <limits>

#include "scene_files.hpp"

using gp::test::input_error;
using gp::test::scene_with;

namespace {
namespace test_scene_errors {

void check_error(const std::string& json, const std::string& field, const std::string& rule,
                 const std::string& value, const gp::SceneOverrides& overrides = {}) {
  INFO(json);
  const auto error = input_error(json, overrides);
  REQUIRE(error);
  CHECK(error->field() == field);
  CHECK(error->rule() == rule);
  CHECK(error->value() == value);
}

const std::string kBall = R"("shapes": [{"type": "circle", "radius": 0.5}])";

TEST_CASE("Malformed JSON is reported at its line and column", "[FR:Verify-Physical_Constraints]") {
  check_error("{\"dt\": 0.01,\n \"duration\": }", "line 2, column 14", "must be valid JSON",
              "syntax error while parsing value - unexpected '}'; expected '[', '{', or a literal");
  check_error("", "line 1, column 1", "must be valid JSON",
              "syntax error while parsing value - unexpected end of input; expected '[', '{', or "
              "a literal");
}

TEST_CASE("A syntax error after a long token is reported with the token cut short",
          "[FR:Verify-Physical_Constraints]") {
  // A line break inside a 30000-character string: nlohmann quotes the whole token read so far.
  // (Matching that message with std::regex overflowed the stack: verification/fuzz/crashes/.)
  const std::string json = R"({"description": ")" + std::string(30000, 'a') + "\n\"}";
  const std::string message =
      "syntax error while parsing value - invalid string: control character U+000A (LF) must be "
      "escaped to \\u000A or \\n; last read: '\"";
  check_error(json, "line 2, column 0", "must be valid JSON",
              message + std::string(200 - message.size(), 'a') + "...");
}

TEST_CASE("A number beyond the range of double is malformed JSON, not infinity",
          "[FR:Verify-Physical_Constraints]") {
  check_error(scene_with(R"({"name": "b", "position": [1e400, 0], "mass": 1})"), "(file)",
              "must be valid JSON", "number overflow parsing '1e400'");
}

TEST_CASE("A document nested deeper than 64 levels is refused where it goes too deep",
          "[FR:Verify-Physical_Constraints]") {
  // Describing so deep a value in a message would recurse once per level: 30000 levels
  // overflowed the stack (verification/fuzz/crashes/ keeps two such inputs).
  const std::string deep = std::string(30000, '[') + std::string(30000, ']');
  // The path is that of the 64th level, whose first element would open the 65th.
  std::string path;
  for (int level = 0; level < 63; ++level) path += "[0]";
  check_error(R"({"dt": 0.01, "duration": 1, "bodies": )" + deep + "}", "bodies" + path,
              "must nest arrays and objects at most 64 deep (scenes need 7)", "level 65");
  check_error(deep, path + "[0]", "must nest arrays and objects at most 64 deep (scenes need 7)",
              "level 65");
}

TEST_CASE("The file must exist and hold a JSON object", "[FR:Verify-Physical_Constraints]") {
  REQUIRE_THROWS_AS(gp::load_scene("/nonexistent/scene.json"), gp::InputError);
  try {
    gp::load_scene("/nonexistent/scene.json");
  } catch (const gp::InputError& e) {
    CHECK(e.field() == "(file)");
    CHECK(e.rule() == "must be an existing regular file");
    CHECK(e.value() == "no such file");
  }
  check_error("[1, 2]", "(file)", "must be an object", "[1,2]");
}

TEST_CASE("Wrong types name the field and show the value", "[FR:Verify-Physical_Constraints]") {
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "mass": "x"})"), "bodies[0].mass",
              "must be a number", "\"x\"");
  check_error(scene_with(R"({"name": 7, "position": [0, 0], "mass": 1})"), "bodies[0].name",
              "must be a string", "7");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "mass": true})"), "bodies[0].mass",
              "must be a number", "true");
  check_error(R"({"dt": 0.01, "duration": 1, "velocity_iterations": 2.5, "bodies": []})",
              "velocity_iterations", "must be an integer (32 bits)", "2.5");
  check_error(R"({"dt": 0.01, "duration": 1, "position_iterations": 3000000000, "bodies": []})",
              "position_iterations", "must be an integer (32 bits)", "3000000000");
  check_error(R"({"dt": 0.01, "duration": 1, "bodies": {}})", "bodies", "must be an array", "{}");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "shapes": 3})"), "bodies[0].shapes",
              "must be an array", "3");
  check_error(scene_with(R"(5)"), "bodies[0]", "must be an object", "5");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "shapes": [[]]})"),
              "bodies[0].shapes[0]", "must be an object", "[]");
}

TEST_CASE("Vectors must be two numbers", "[FR:Verify-Physical_Constraints]") {
  check_error(scene_with(R"({"name": "b", "position": [1, 2, 3], "mass": 1})"),
              "bodies[0].position", "must be an array of 2 numbers [x, y]", "[1,2,3]");
  check_error(scene_with(R"({"name": "b", "position": 1, "mass": 1})"), "bodies[0].position",
              "must be an array of 2 numbers [x, y]", "1");
  check_error(scene_with(R"({"name": "b", "position": [0, "a"], "mass": 1})"),
              "bodies[0].position[1]", "must be a number", "\"a\"");
  check_error(R"({"gravity": [0], "dt": 0.01, "duration": 1, "bodies": []})", "gravity",
              "must be an array of 2 numbers [x, y]", "[0]");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "polygon", "vertices": [[0, 0], [1, 0], [0]]}]})"),
              "bodies[0].shapes[0].vertices[2]", "must be an array of 2 numbers [x, y]", "[0]");
}

TEST_CASE("Unknown fields are rejected at every level", "[FR:Verify-Physical_Constraints]") {
  check_error(R"({"gravty": [0, -9.81], "dt": 0.01, "duration": 1, "bodies": []})", "gravty",
              "is not a known field (known: description, gravity, G, integrator, dt, duration, "
              "output_dt, velocity_iterations, velocity_tolerance, direct_solve_points, "
              "direct_solve_uneven_points, direct_solve_mass_ratio, direct_solve_resting_points, "
              "position_iterations, restitution_threshold, sleep, sleep_speed, "
              "sleep_angular_speed, time_to_sleep, coloured_island_contacts, island_part_contacts, "
              "island_parts, bodies)",
              "[0,-9.81]");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "mas": 1})"), "bodies[0].mas",
              "is not a known field (known: name, type, position, angle, velocity, "
              "angular_velocity, mass, moment, force, force_point, torque, shapes)",
              "1");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "circle", "radius": 1, "restitusion": 0.5}]})"),
              "bodies[0].shapes[0].restitusion",
              "is not a known field (known: type, radius, center, restitution, friction, density)",
              "0.5");
  // A field of another shape type is as wrong as a typo.
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "box", "width": 1, "height": 1, "radius": 1}]})"),
              "bodies[0].shapes[0].radius",
              "is not a known field (known: type, width, height, center, restitution, friction, "
              "density)",
              "1");
}

TEST_CASE("A key given twice in one object is rejected", "[FR:Verify-Physical_Constraints]") {
  check_error(R"({"dt": 0.01, "duration": 1, "dt": 0.02, "bodies": []})", "dt",
              "is given twice in the same object", "\"dt\"");
  check_error(scene_with(R"({"name": "a", "position": [0, 0], "mass": 1},
                            {"name": "b", "position": [0, 0], "mass": 1, "mass": -1})"),
              "bodies[1].mass", "is given twice in the same object", "\"mass\"");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "shapes": [
      {"type": "circle", "radius": 1, "center": [0, 0]},
      {"type": "circle", "radius": 1, "radius": 2}]})"),
              "bodies[0].shapes[1].radius", "is given twice in the same object", "\"radius\"");
}

TEST_CASE("Missing required fields are named", "[FR:Verify-Physical_Constraints]") {
  check_error(R"({"duration": 1, "bodies": []})", "dt", "is required", "none");
  check_error(R"({"dt": 0.01, "bodies": []})", "duration", "is required", "none");
  check_error(R"({"dt": 0.01, "duration": 1})", "bodies", "is required", "none");
  check_error(scene_with(R"({"position": [0, 0], "mass": 1})"), "bodies[0].name", "is required",
              "none");
  check_error(scene_with(R"({"name": "b", "mass": 1})"), "bodies[0].position", "is required",
              "none");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "shapes": [{"radius": 1}]})"),
              "bodies[0].shapes[0].type", "is required", "none");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "shapes": [{"type": "circle"}]})"),
              "bodies[0].shapes[0].radius", "is required", "none");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "segment", "a": [0, 0]}]})"),
              "bodies[0].shapes[0].b", "is required", "none");
}

TEST_CASE("Body names are unique CSV fields", "[FR:Verify-Physical_Constraints]") {
  check_error(scene_with(R"({"name": "ball", "position": [0, 0], "mass": 1},
                            {"name": "wall", "position": [5, 0], "mass": 1},
                            {"name": "ball", "position": [9, 0], "mass": 1})"),
              "bodies[2].name", "must be unique (also the name of bodies[0])", "\"ball\"");
  for (const char* name : {"", "a,b", "say \\\"hi\\\"", "two\\nlines"}) {
    check_error(
        scene_with(R"({"name": ")" + std::string(name) + R"(", "position": [0, 0], "mass": 1})"),
        "bodies[0].name", "must be non-empty, without commas, quotes or line breaks (a CSV field)",
        std::string("\"") + name + "\"");  // the name's JSON text, shown as given
  }
}

TEST_CASE("Unknown names of body types, shape types and integrators are rejected",
          "[FR:Verify-Physical_Constraints]") {
  check_error(scene_with(R"({"name": "b", "type": "dynamc", "position": [0, 0], "mass": 1})"),
              "bodies[0].type", "must be one of dynamic, static, kinematic", "\"dynamc\"");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "cirle", "radius": 1}]})"),
              "bodies[0].shapes[0].type", "must be one of circle, box, polygon, segment",
              "\"cirle\"");
  check_error(R"({"integrator": "euler", "dt": 0.01, "duration": 1, "bodies": []})", "integrator",
              "must be one of symplectic_euler, velocity_verlet, rk4", "\"euler\"");
}

TEST_CASE("Fields that have no effect on static and kinematic bodies are rejected",
          "[FR:Verify-Physical_Constraints]") {
  check_error(scene_with(R"({"name": "wall", "type": "static", "position": [0, 0],
      "velocity": [1, 0], )" +
                         kBall + "}"),
              "bodies[0].velocity", "has no effect on a static body (it never moves)", "[1,0]");
  check_error(scene_with(R"({"name": "lift", "type": "kinematic", "position": [0, 0],
      "mass": 3, )" + kBall +
                         "}"),
              "bodies[0].mass",
              "has no effect on a kinematic body (only dynamic bodies have mass and respond to "
              "forces)",
              "3");
}

TEST_CASE("The time stepping must be positive and bounded", "[FR:Verify-Physical_Constraints]") {
  check_error(R"({"dt": 0, "duration": 1, "bodies": []})", "dt", "must be > 0 (a time step)", "0");
  check_error(R"({"dt": 0.01, "duration": -1, "bodies": []})", "duration",
              "must be a finite number >= 0", "-1");
  check_error(R"({"dt": 0.01, "duration": 1, "output_dt": -0.5, "bodies": []})", "output_dt",
              "must be > 0 (a time step)", "-0.5");
  check_error(R"({"dt": 1e-9, "duration": 10, "bodies": []})", "duration",
              "must be at most 1e9 time steps (duration / dt)", "10");
  check_error(R"({"dt": 1, "duration": 10, "output_dt": 1e-9, "bodies": []})", "duration",
              "must be at most 1e9 output intervals (duration / output_dt)", "10");
}

TEST_CASE("Settings are checked", "[FR:Verify-Physical_Constraints]") {
  check_error(R"({"G": -1, "dt": 0.01, "duration": 1, "bodies": []})", "G", "must be >= 0", "-1");
  check_error(R"({"restitution_threshold": -0.1, "dt": 0.01, "duration": 1, "bodies": []})",
              "restitution_threshold", "must be >= 0", "-0.10000000000000001");
  check_error(R"({"sleep": "yes", "dt": 0.01, "duration": 1, "bodies": []})", "sleep",
              "must be true or false", "\"yes\"");
  check_error(R"({"sleep_speed": -0.5, "dt": 0.01, "duration": 1, "bodies": []})", "sleep_speed",
              "must be >= 0", "-0.5");
  check_error(R"({"time_to_sleep": -1, "dt": 0.01, "duration": 1, "bodies": []})", "time_to_sleep",
              "must be >= 0", "-1");
  check_error(R"({"coloured_island_contacts": -1, "dt": 0.01, "duration": 1, "bodies": []})",
              "coloured_island_contacts", "must be >= 0 (0: never)", "-1");
  check_error(R"({"island_part_contacts": -2, "dt": 0.01, "duration": 1, "bodies": []})",
              "island_part_contacts", "must be >= 0 (0: never)", "-2");
  for (const char* parts : {"1", "3", "128"}) {
    check_error(std::string(R"({"island_parts": )") + parts +
                    R"(, "dt": 0.01, "duration": 1, "bodies": []})",
                "island_parts", "must be a power of two from 2 to 64", parts);
  }
  // The direct solve's settings: setting, rule, value.
  const std::string direct_solve[][3] = {
      {"direct_solve_points", "must be in [0, 1024]", "2000"},
      {"direct_solve_uneven_points", "must be in [0, 1024]", "-1"},
      {"direct_solve_mass_ratio", "must be >= 1 (heaviest over lightest)", "0.5"},
      {"direct_solve_resting_points", "must be in [0, 65536]", "70000"}};
  for (const auto& [setting, rule, value] : direct_solve) {
    check_error("{\"" + setting + "\": " + value + R"(, "dt": 0.01, "duration": 1, "bodies": []})",
                setting, rule, value);
  }
  check_error(R"({"velocity_tolerance": -1e-5, "dt": 0.01, "duration": 1, "bodies": []})",
              "velocity_tolerance", "must be >= 0", "-1.0000000000000001e-05");
  check_error(R"({"velocity_iterations": -1, "dt": 0.01, "duration": 1, "bodies": []})",
              "velocity_iterations", "must be in [0, 1000]", "-1");
  // Two billion passes a step hung the run (a fuzz input kept in verification/fuzz/crashes/).
  check_error(R"({"position_iterations": 2000000000, "dt": 0.01, "duration": 1, "bodies": []})",
              "position_iterations", "must be in [0, 1000]", "2000000000");
}

TEST_CASE("The SRS data constraints on bodies name the field of the file",
          "[FR:Verify-Physical_Constraints]") {
  const std::string others = R"({"name": "a", "position": [0, 0], "mass": 1},
      {"name": "b", "position": [0, 0], "mass": 1}, {"name": "c", "position": [0, 0], "mass": 1},)";
  check_error(scene_with(others + R"({"name": "d", "position": [0, 0], "mass": -1})"),
              "bodies[3].mass", "must be > 0 (SRS data constraint m > 0)", "-1");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "mass": 1, "moment": 0})"),
              "bodies[0].moment", "must be > 0 (SRS data constraint I > 0)", "0");
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "angle": 7, )" + kBall + "}"),
              "bodies[0].angle", "must be in [0, 2π] (SRS software constraint on ϕ)", "7");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "circle", "radius": 1, "restitution": 1.5}]})"),
              "bodies[0].shapes[0].restitution", "must be in [0, 1] (SRS data constraint on C_R)",
              "1.5");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "circle", "radius": 1, "friction": -0.1}]})"),
              "bodies[0].shapes[0].friction", "must be >= 0", "-0.10000000000000001");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "circle", "radius": 1, "density": 0}]})"),
              "bodies[0].shapes[0].density", "must be > 0 (mass per unit area)", "0");
  check_error(scene_with(R"({"name": "b", "position": [0, 0]})"), "bodies[0].mass",
              "is required for a dynamic body without area", "none");
}

TEST_CASE("Shapes whose mass overflows or underflows a double are refused",
          "[FR:Verify-Physical_Constraints]") {
  // Finite inputs, but a disc of radius 1e300 has an infinite area, so no centre of mass: this
  // escaped as std::invalid_argument from Space::add_body (verification/fuzz/crashes/).
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "circle", "radius": 1e300}]})"),
              "bodies[0].shapes",
              "must give the body a finite mass (> 0 if dynamic), centre of mass and moment of "
              "inertia",
              "mass inf, moment nan, centre [nan, nan]");
  // A disc of radius 1e-200 has area 0 as a double: a dynamic body of no mass.
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "circle", "radius": 1e-200}]})"),
              "bodies[0].shapes",
              "must give the body a finite mass (> 0 if dynamic), centre of mass and moment of "
              "inertia",
              "mass 0, moment 0, centre [0, 0]");
}

TEST_CASE("Degenerate shapes are reported at the shape's path",
          "[FR:Verify-Physical_Constraints]") {
  check_error(scene_with(R"({"name": "a", "position": [0, 0], "mass": 1},
      {"name": "b", "position": [0, 0], "mass": 1},
      {"name": "c", "position": [0, 0], "shapes": [{"type": "circle", "radius": -1}]})"),
              "bodies[2].shapes[0]", "circle radius must be finite and > 0", "-1");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "segment", "a": [1, 1], "b": [1, 1]}]})"),
              "bodies[0].shapes[0]", "segment ends must be distinct", "a = (1, 1) and b = (1, 1)");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "polygon", "vertices": [[0, 0], [1, 1], [3, 3]]}]})"),
              "bodies[0].shapes[0]", "polygon area must be > 0 (vertices not all collinear)", "0");
  check_error(scene_with(R"({"name": "b", "position": [0, 0],
      "shapes": [{"type": "polygon", "vertices": [[0, 0], [1, 1], [1, 1], [0, 0]]}]})"),
              "bodies[0].shapes[0]", "polygon needs at least 3 distinct vertices", "2");
  // A message without ", got": the shape itself is the offending value.
  check_error(scene_with(R"({"name": "b", "position": [0, 0], "shapes": [{"type": "polygon",
      "vertices": [[0, 0], [2, 0], [1, 0.2], [2, 2], [0, 2]]}]})"),
              "bodies[0].shapes[0]",
              "polygon must be strictly convex (no reflex or straight corner): vertex (1, 0.2) is "
              "not",
              R"({"type":"polygon","vertices":[[0,0],[2,0],[1,0.2],[2,2],[0,2]]})");
}

TEST_CASE("Overrides are checked like the file's values", "[FR:Verify-Physical_Constraints]") {
  gp::SceneOverrides overrides;
  overrides.dt = -1.0;
  check_error(scene_with(""), "dt", "must be > 0 (a time step)", "-1", overrides);
  overrides = {};
  overrides.integrator = "leapfrog";
  check_error(scene_with(""), "integrator", "must be one of symplectic_euler, velocity_verlet, rk4",
              "\"leapfrog\"", overrides);
  // Not UTF-8: the value is shown with U+FFFD (this threw nlohmann's type_error before).
  overrides.integrator = "\xff";
  check_error(scene_with(""), "integrator", "must be one of symplectic_euler, velocity_verlet, rk4",
              "\"\xef\xbf\xbd\"", overrides);
  overrides = {};
  overrides.duration = std::numeric_limits<double>::infinity();
  check_error(scene_with(""), "duration", "must be a finite number >= 0", "inf", overrides);
}

}  // namespace test_scene_errors
}  // namespace
