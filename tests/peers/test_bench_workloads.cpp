// The benchmark workloads and the summary of `gamephysics_bench` (NFR:Performance).
#include <catch2/catch.hpp>

#include <sstream>
#include <variant>

#include "verification/bench/bench_engine.hpp"
#include "verification/bench/summary.hpp"
#include "verification/bench/workloads.hpp"

namespace {
namespace test_bench_workloads {

bool same_shape(const gp::Shape& a, const gp::Shape& b) {
  if (a.kind() != b.kind()) return false;
  if (const auto* c = std::get_if<gp::Circle>(&a.geometry())) {
    const auto& d = std::get<gp::Circle>(b.geometry());
    return c->center == d.center && c->radius == d.radius;
  }
  const auto* s = std::get_if<gp::Segment>(&a.geometry());
  const auto* t = std::get_if<gp::Segment>(&b.geometry());
  return s && t && s->a == t->a && s->b == t->b && s->radius == t->radius;
}

TEST_CASE("rain built in code is scenes/rain1000.json to the last bit", "[NFR:Performance]") {
  const gp::Scene file = gp::load_scene(std::string(GP_SOURCE_DIR) + "/scenes/rain1000.json");
  const gp::Scene code = gp::bench::rain(1000);
  CHECK(code.settings.gravity == file.settings.gravity);
  CHECK(code.dt == file.dt);
  CHECK(code.duration == file.duration);
  CHECK(code.output_dt == file.output_dt);
  REQUIRE(code.bodies.size() == file.bodies.size());
  for (std::size_t i = 0; i < file.bodies.size(); ++i) {
    const gp::BodyDef& a = code.bodies[i];
    const gp::BodyDef& b = file.bodies[i];
    INFO(b.name);
    CHECK(a.name == b.name);
    CHECK(a.type == b.type);
    CHECK(a.position == b.position);
    CHECK(a.velocity == b.velocity);
    CHECK(a.mass == b.mass);
    REQUIRE(a.shapes.size() == b.shapes.size());
    for (std::size_t k = 0; k < a.shapes.size(); ++k) {
      CHECK(same_shape(a.shapes[k].shape, b.shapes[k].shape));
      CHECK(a.shapes[k].friction == b.shapes[k].friction);
      CHECK(a.shapes[k].restitution == b.shapes[k].restitution);
      CHECK(a.shapes[k].density == b.shapes[k].density);
    }
  }
}

TEST_CASE("Larger rain scenes widen the box and keep 25 rows", "[NFR:Performance]") {
  const gp::Scene rain = gp::bench::rain(4000);
  REQUIRE(rain.bodies.size() == 4001);
  const auto& floor = std::get<gp::Segment>(rain.bodies[0].shapes[0].shape.geometry());
  CHECK(floor.b.x() - floor.a.x() == 320.0);
  CHECK(rain.bodies.back().position.y() == 5.0 + 24 * 1.5);
  CHECK_THROWS_AS(gp::bench::rain(1010), std::invalid_argument);
  CHECK(gp::bench::free_fall(10).bodies.size() == 10);
}

TEST_CASE("Every engine runs a workload and the summary gives medians and ratios",
          "[NFR:Performance]") {
  const gp::Scene scene = gp::bench::free_fall(4);
  for (auto engine : gp::bench::kEngines) {
    gp::bench::EngineRun run(engine, scene);
    run.step(scene.dt);
    INFO(gp::bench::engine_label(engine));
    CHECK(run.state(3).position.y() > scene.bodies[3].position.y());
    CHECK_FALSE(run.describe().empty());
  }
  // Three repetitions of ours (10, 30, 20 ms) and one of chipmunk (5 ms).
  std::vector<benchmark::BenchmarkReporter::Run> runs;
  for (const auto& [name, ms] : {std::pair{"w/ours", 10.0},
                                 {"w/ours", 30.0},
                                 {"w/ours", 20.0},
                                 {"w/chipmunk-default", 5.0}}) {
    benchmark::BenchmarkReporter::Run run;
    run.run_name.function_name = name;
    run.time_unit = benchmark::kMillisecond;
    run.iterations = 1;
    run.real_accumulated_time = ms / 1e3;
    run.counters["moved_m"] = 0.25;
    run.counters["heap_bytes"] = 2048.0;
    runs.push_back(run);
  }
  const std::vector<gp::bench::Workload> list{{"w", scene, 100, gp::BodyId{0}}};
  const auto all = gp::bench::figures(list, runs);
  REQUIRE(all.size() == 2);
  CHECK(all[0].median_ms == Approx(20.0));
  CHECK(all[0].min_ms == Approx(10.0));
  CHECK(all[0].max_ms == Approx(30.0));
  CHECK(all[0].stddev_ms == Approx(10.0));
  CHECK(all[0].body_steps_per_s == Approx(4 * 100 / 0.020));
  CHECK(all[1].moved_m == 0.25);
  CHECK(all[1].heap_bytes == 2048.0);
  CHECK(all[1].bodies == 4);
  std::ostringstream out;
  gp::bench::print_summary(out, all);
  CHECK_THAT(out.str(), Catch::Contains("4.00"));    // ours/chipmunk: 20 ms / 5 ms
  CHECK_THAT(out.str(), Catch::Contains(" 512\n"));  // heap per body: 2048 B over 4 bodies
  CHECK_THAT(out.str(), Catch::Contains("moved 0.25 m in chipmunk-default"));
}

TEST_CASE("The summary reads the statistics when only those were displayed", "[NFR:Performance]") {
  std::vector<benchmark::BenchmarkReporter::Run> runs;
  for (const auto& [statistic, ms] :
       {std::pair{"median", 20.0}, {"min", 10.0}, {"max", 30.0}, {"stddev", 4.0}}) {
    benchmark::BenchmarkReporter::Run run;
    run.run_name.function_name = "w/box2d-matched";
    run.run_type = benchmark::BenchmarkReporter::Run::RT_Aggregate;
    run.aggregate_name = statistic;
    run.repetitions = 5;
    run.time_unit = benchmark::kMillisecond;
    run.iterations = 1;
    run.real_accumulated_time = ms / 1e3;
    runs.push_back(run);
  }
  const std::vector<gp::bench::Workload> list{{"w", gp::bench::free_fall(1), 10, std::nullopt}};
  const auto all = gp::bench::figures(list, runs);
  REQUIRE(all.size() == 1);
  CHECK(all[0].repetitions == 5);
  CHECK(all[0].median_ms == Approx(20.0));
  CHECK(all[0].min_ms == Approx(10.0));
  CHECK(all[0].max_ms == Approx(30.0));
  CHECK(all[0].stddev_ms == Approx(4.0));
  CHECK(all[0].moved_m < 0.0);
}

TEST_CASE("The summary gives each engine's heap per disc added from rain1000 to rain4000",
          "[NFR:Performance]") {
  const auto with_heap = [](const char* workload, const char* engine, double bytes) {
    gp::bench::Figures f{workload, engine, 1};
    f.heap_bytes = bytes;
    return f;
  };
  // 3000 discs more take 3 MB more in ours: 1000 B each. Box2D has no rain4000 figure, and
  // Chipmunk2D's rain4000 was not measured (negative), so neither gets a figure.
  const std::vector<gp::bench::Figures> all{
      with_heap("rain1000", "ours", 1.5e6), with_heap("rain1000", "chipmunk", 2e6),
      with_heap("rain1000", "box2d", 1e6), with_heap("rain4000", "ours", 4.5e6),
      with_heap("rain4000", "chipmunk", -1.0)};
  const auto per_body = gp::bench::heap_per_added_body(all);
  REQUIRE(per_body.size() == 1);
  CHECK(per_body[0].first == "ours");
  CHECK(per_body[0].second == Approx(1000.0));
  std::ostringstream out;
  gp::bench::print_summary(out, all);
  CHECK_THAT(out.str(), Catch::Contains("rain4000 (held at the end of the run): ours 1000 B\n"));
}

TEST_CASE("The summary gives each engine's growth of the time per step from rain1000 on",
          "[NFR:Performance]") {
  const auto timed = [](const char* workload, const char* engine, std::size_t bodies,
                        std::size_t steps, double median_ms, double min_ms) {
    gp::bench::Figures f{workload, engine, 3};
    f.median_ms = median_ms;
    f.min_ms = min_ms;
    f.bodies = bodies;
    f.steps = steps;
    return f;
  };
  // Ours: 1000 steps each, 500 → 3000 → 12,000 ms by medians (6× and 24×), 400 → 2000 → 10,000
  // ms by the fastest runs (5× and 25×). Box2D's rain4000 ran 500 steps: 1200 ms is 2.4 ms a
  // step against 0.3, 8×. Chipmunk2D has no rain1000, so no growth.
  const std::vector<gp::bench::Figures> all{
      timed("rain1000", "ours", 1001, 1000, 500.0, 400.0),
      timed("rain1000", "box2d", 1001, 1000, 300.0, 300.0),
      timed("rain4000", "ours", 4001, 1000, 3000.0, 2000.0),
      timed("rain4000", "box2d", 4001, 500, 1200.0, 1200.0),
      timed("rain4000", "chipmunk", 4001, 1000, 1000.0, 1000.0),
      timed("rain16000", "ours", 16001, 1000, 12000.0, 10000.0)};
  const auto growth = gp::bench::time_growth_over_bodies(all);
  REQUIRE(growth.size() == 3);
  CHECK(growth[0].engine == "ours");
  CHECK(growth[0].workload == "rain4000");
  CHECK(growth[0].by_medians == Approx(6.0));
  CHECK(growth[0].by_fastest == Approx(5.0));
  // 4001 ln 4001 / (1001 ln 1001), by hand: 33,185.5 / 6915.7.
  CHECK(growth[0].n_log_n == Approx(4.7986).epsilon(1e-4));
  CHECK(growth[1].workload == "rain16000");
  CHECK(growth[1].by_medians == Approx(24.0));
  CHECK(growth[1].by_fastest == Approx(25.0));
  // 16,001 ln 16,001 / (1001 ln 1001): 154,896 / 6915.7.
  CHECK(growth[1].n_log_n == Approx(22.398).epsilon(1e-4));
  CHECK(growth[2].engine == "box2d");
  CHECK(growth[2].by_medians == Approx(8.0));
  std::ostringstream out;
  gp::bench::print_summary(out, all);
  CHECK_THAT(out.str(), Catch::Contains("ours to rain4000 6.00x and 5.00x (N log N 4.80x); ours "
                                        "to rain16000 24.00x and 25.00x (N log N 22.40x); box2d "
                                        "to rain4000 8.00x and 8.00x (N log N 4.80x)\n"));
}

}  // namespace test_bench_workloads
}  // namespace
