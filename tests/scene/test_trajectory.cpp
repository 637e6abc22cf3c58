// The trajectory CSV: its header, one row per body per instant, and numbers that read back to
// the same doubles.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "engine/output/trajectory.hpp"
#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene_files.hpp"

namespace {
namespace test_trajectory {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

double number(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  REQUIRE(*end == '\0');
  return value;
}

// A spinning, moving body and a point mass: every column takes values other than 0 and 1.
const std::string kScene = R"({"gravity": [0.3, -9.81], "dt": 0.01, "duration": 0.7,
    "output_dt": 0.1, "bodies": [
    {"name": "spinner", "position": [0.1, 0.2], "angle": 6.2, "velocity": [1.1, 2.3],
     "angular_velocity": 3.7, "shapes": [{"type": "box", "width": 0.3, "height": 0.7}]},
    {"name": "dot", "position": [-1, 1], "velocity": [-0.7, 0.1], "mass": 2}]})";

TEST_CASE("The trajectory reads back to the engine's state, to the bit",
          "[FR:Calculate-Translation-Over-Time][FR:Calculate-Rotation-Over-Time]") {
  const gp::Scene scene = gp::test::load(kScene);
  const auto space = gp::build_space(scene);
  std::ostringstream csv;
  gp::TrajectoryCsv writer(csv);
  std::vector<std::pair<double, std::vector<gp::BodyState>>> expected;
  gp::run_scene(*space, scene, [&](double t) {
    writer.write(t, *space);
    expected.push_back({t, {space->state(0), space->state(1)}});
  });

  std::istringstream in(csv.str());
  std::string line;
  REQUIRE(std::getline(in, line));
  CHECK(line == "t,body,x,y,angle,vx,vy,omega");
  std::size_t rows = 0;
  for (const auto& [t, states] : expected) {
    for (std::size_t body = 0; body < states.size(); ++body, ++rows) {
      REQUIRE(std::getline(in, line));
      const auto fields = split(line);
      REQUIRE(fields.size() == 8);
      const gp::BodyState& s = states[body];
      CHECK(number(fields[0]) == t);
      CHECK(fields[1] == space->name(static_cast<gp::BodyId>(body)));
      CHECK(number(fields[2]) == s.position.x());
      CHECK(number(fields[3]) == s.position.y());
      CHECK(number(fields[4]) == s.angle);
      CHECK(number(fields[5]) == s.velocity.x());
      CHECK(number(fields[6]) == s.velocity.y());
      CHECK(number(fields[7]) == s.angular_velocity);
      // SRS output constraint 0 ≤ ϕ ≤ 2π, reported in [0, 2π).
      CHECK(s.angle >= 0.0);
      CHECK(s.angle < 2 * std::numbers::pi);
    }
  }
  CHECK(rows == 2 * 8);  // t = 0, 0.1, …, 0.7
  CHECK_FALSE(std::getline(in, line));
}

TEST_CASE("Numbers are written with 17 significant digits",
          "[FR:Calculate-Translation-Over-Time]") {
  const gp::Scene scene = gp::test::load(gp::test::scene_with(
      R"({"name": "third", "position": [0.1, 0.30000000000000004], "mass": 1})"));
  const auto space = gp::build_space(scene);
  std::ostringstream csv;
  gp::TrajectoryCsv(csv).write(1.0 / 3.0, *space);
  CHECK(csv.str() ==
        "t,body,x,y,angle,vx,vy,omega\n"
        "0.33333333333333331,third,0.10000000000000001,0.30000000000000004,0,0,0,0\n");
}

// printf is the reference: the CSV's numbers are defined as its "%.17g".
std::string printf_17g(double value) {
  std::array<char, 32> text{};
  const int length = std::snprintf(text.data(), text.size(), "%.17g", value);
  return {text.data(), static_cast<std::size_t>(length)};
}

std::string written(double value) {
  std::ostringstream out;
  gp::write_number(out, value);
  return out.str();
}

TEST_CASE("Every number is written as printf's %.17g writes it",
          "[FR:Calculate-Translation-Over-Time]") {
  using limits = std::numeric_limits<double>;
  for (double value : {0.0,
                       -0.0,
                       1.0,
                       -1.0,
                       0.1,
                       1.0 / 3.0,
                       1e16,
                       1e17,
                       123456789012345678.0,
                       1e-4,
                       9.9999999999999995e-5,
                       1e-5,
                       limits::min(),
                       limits::denorm_min(),
                       limits::max(),
                       -limits::max(),
                       limits::infinity(),
                       -limits::infinity(),
                       limits::quiet_NaN(),
                       2 * std::numbers::pi}) {
    CAPTURE(value);
    CHECK(written(value) == printf_17g(value));
  }
  // Doubles of every exponent and sign, as random bit patterns.
  std::mt19937_64 bits(17);
  for (int i = 0; i < 100000; ++i) {
    const std::uint64_t pattern = bits();
    double value = 0.0;
    std::memcpy(&value, &pattern, sizeof value);
    if (std::isnan(value)) continue;  // NaN's sign and payload are printf's own choice
    CAPTURE(pattern);
    REQUIRE(written(value) == printf_17g(value));
  }
}

}  // namespace test_trajectory
}  // namespace
