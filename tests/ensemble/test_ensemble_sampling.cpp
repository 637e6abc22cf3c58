// The draws of an ensemble: the sampler's points, the perturbed inputs and the summary, against
// hand computations and the properties of a uniform distribution.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "scene/input_error.hpp"
#include "verification/ensemble/ensemble.hpp"
#include "verification/ensemble/perturbation.hpp"
#include "verification/ensemble/sampler.hpp"
#include "verification/ensemble/summary.hpp"
#include "verification/ensemble/uncertainty.hpp"

namespace {
namespace test_ensemble_sampling {

using namespace gp;
using namespace gp::verification;

Scene ball_scene() {
  Scene s = parse_scene(R"({"gravity": [0, -9.81], "dt": 0.01, "duration": 1, "bodies": [
    {"name": "ground", "type": "static", "position": [0, 0], "shapes": [{"type": "segment", "a": [-5, 0], "b": [5, 0],
     "restitution": 0.8}]},
    {"name": "ball", "position": [0, 2], "velocity": [1, 0], "mass": 2,
     "shapes": [{"type": "circle", "radius": 0.5, "restitution": 0.95, "friction": 0.3}]}]})");
  return s;
}

TEST_CASE("sample i's point depends on i and the seed alone", "[ensemble][sampler]") {
  for (Sampler sampler : {Sampler::Sobol, Sampler::Random}) {
    const auto a = unit_point(sampler, 7, 5, 123);
    CHECK(a == unit_point(sampler, 7, 5, 123));
    CHECK(a != unit_point(sampler, 7, 5, 124));
    CHECK(a != unit_point(sampler, 8, 5, 123));
    for (double u : a) CHECK((u >= 0.0 && u < 1.0));
  }
}

TEST_CASE("the Sobol points fill each axis evenly, better than random ones",
          "[ensemble][sampler]") {
  // In 1024 points, each of the 64 bins of an axis should hold 16. A (0, m, s)-net, shifted
  // modulo 1, holds exactly 16 in each bin give or take the points split by the shift (at most
  // 1 per bin edge); random points deviate by about √16 = 4.
  const std::size_t n = 1024, bins = 64, dimension = 6;
  for (std::size_t k = 0; k < dimension; ++k) {
    std::vector<int> sobol(bins), random(bins);
    for (std::size_t i = 0; i < n; ++i) {
      ++sobol[static_cast<std::size_t>(unit_point(Sampler::Sobol, 3, dimension, i)[k] * bins)];
      ++random[static_cast<std::size_t>(unit_point(Sampler::Random, 3, dimension, i)[k] * bins)];
    }
    const auto spread = [](const std::vector<int>& v) {
      return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
    };
    CHECK(spread(sobol) <= 2);
    CHECK(spread(random) > 2);
  }
}

TEST_CASE("Sobol refuses more dimensions than it has direction numbers", "[ensemble][sampler]") {
  CHECK_THROWS_AS(unit_point(Sampler::Sobol, 0, sobol_max_dimension() + 1, 0),
                  std::invalid_argument);
  CHECK(unit_point(Sampler::Random, 0, sobol_max_dimension() + 1, 0).size() ==
        sobol_max_dimension() + 1);
}

TEST_CASE("the perturbed inputs are the scene's non-zero inputs with their SRS spreads",
          "[ensemble][perturbation]") {
  const Scene scene = ball_scene();
  const auto inputs = perturbed_inputs(scene, srs_spreads());
  std::vector<std::string> names;
  for (const auto& input : inputs) names.push_back(input.name);
  // The ground is static: only its surface; the ball's zero y-velocity, angle and ω stay put.
  CHECK(names == std::vector<std::string>{"dt", "ground.shape0.restitution", "ball.mass", "ball.y",
                                          "ball.vx", "ball.shape0.restitution",
                                          "ball.shape0.friction"});
  for (const auto& input : inputs) CHECK(input.relative == 0.1);
}

TEST_CASE("a point maps to values within x (1 ± u), C_R clamped to 0 to 1",
          "[ensemble][perturbation]") {
  const Scene scene = ball_scene();
  const Spreads spreads = srs_spreads();
  const auto inputs = perturbed_inputs(scene, spreads);
  // The centre of the cube is the nominal scene; its corner is 1.1 times every input.
  const std::vector<double> centre(inputs.size(), 0.5), corner(inputs.size(), 1.0);
  const Scene same = perturbed_scene(scene, spreads, input_values(inputs, centre));
  CHECK(same.dt == scene.dt);
  CHECK(*same.bodies[1].mass == 2.0);
  const Scene high = perturbed_scene(scene, spreads, input_values(inputs, corner));
  CHECK(high.dt == Approx(0.011).epsilon(1e-14));
  CHECK(*high.bodies[1].mass == Approx(2.2).epsilon(1e-14));
  CHECK(high.bodies[1].position.y() == Approx(2.2).epsilon(1e-14));
  CHECK(high.bodies[1].velocity.x() == Approx(1.1).epsilon(1e-14));
  CHECK(high.bodies[1].shapes[0].restitution == 1.0);  // 0.95 · 1.1 = 1.045, clamped
  CHECK(high.bodies[0].shapes[0].restitution == Approx(0.88).epsilon(1e-14));
  CHECK(high.bodies[1].shapes[0].friction == Approx(0.33).epsilon(1e-14));
}

TEST_CASE("a body without a mass has its densities scaled", "[ensemble][perturbation]") {
  Scene scene = ball_scene();
  scene.bodies[1].mass.reset();
  const Spreads spreads = srs_spreads();
  const auto inputs = perturbed_inputs(scene, spreads);
  CHECK(inputs[2].name == "ball.density_factor");
  const std::vector<double> low(inputs.size(), 0.0);
  const Scene light = perturbed_scene(scene, spreads, input_values(inputs, low));
  CHECK(light.bodies[1].shapes[0].density == Approx(0.9).epsilon(1e-14));
}

TEST_CASE("the summary's statistics match a hand computation", "[ensemble][summary]") {
  // x = 1..5 (one sample failed): mean 3, sample std √2.5, median 3; the 5% point lies at
  // position 0.2 between 1 and 2 (1.2), the 95% point at 3.8 (4.8).
  std::istringstream csv(
      "sample,x,oracle,error\n0,3,ok,\n1,1,ok,\n2,,ok,\"run failed, badly\"\n3,5,ok,\n4,2,ok,\n"
      "5,4,ok,\n");
  const auto s = summarize_samples(csv);
  CHECK(s["samples"] == 6);
  CHECK(s["failed"] == 1);
  CHECK(s["errors"][0] == "sample 2: run failed, badly");
  const auto& x = s["columns"]["x"];
  CHECK(x["count"] == 5);
  CHECK(x["mean"].get<double>() == Approx(3.0));
  CHECK(x["std"].get<double>() == Approx(std::sqrt(2.5)));
  CHECK(x["q05"].get<double>() == Approx(1.2));
  CHECK(x["q50"].get<double>() == Approx(3.0));
  CHECK(x["q95"].get<double>() == Approx(4.8));
  CHECK(!s["columns"].contains("oracle"));
}

TEST_CASE("an uncertainty file is checked like a scene file", "[ensemble][uncertainty]") {
  const auto path = std::filesystem::temp_directory_path() / "gp_spreads_test.json";
  const auto error_of = [&](const std::string& text) {
    std::ofstream(path) << text;
    try {
      read_spreads(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(error_of(R"({"mass": 1.5})") ==
        "mass: must be a relative spread u with 0 <= u < 1, got 1.5");
  CHECK(error_of(R"({"mas": 0.1})").starts_with("mas: is not a known field"));
  CHECK(error_of(R"({"mass": "ten"})").starts_with("mass: must be a number"));
  std::ofstream(path) << R"({"mass": 0.05, "dt": 0.2})";
  const Spreads s = read_spreads(path);
  CHECK(s.of("mass") == 0.05);
  CHECK(s.of("dt") == 0.2);
  CHECK(s.of("velocity") == 0.0);
  std::filesystem::remove(path);
}

}  // namespace test_ensemble_sampling
}  // namespace
