// The section "speed against the peers" of `gamephysics verify`, built from given timings (no run
// is timed here).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "verification/bench/workloads.hpp"
#include "verification/suite/speed_report.hpp"
#include "verification/suite/speed_table.hpp"

namespace {
namespace test_speed_table {

using Cells = std::vector<std::string>;

// pyramid20 (4 bodies, 100 steps, body 0 watched) and rain1000 (2 bodies, 50 steps) with made-up
// timings [ms] of three and one runs.
gp::verification::SpeedTable fake_table() {
  const gp::bench::Workload pyramid{"pyramid20", gp::bench::free_fall(4), 100, gp::BodyId{0}};
  const gp::bench::Workload rain{"rain1000", gp::bench::free_fall(2), 50, std::nullopt};
  gp::verification::SpeedTable table;
  table.figures = {gp::bench::figures_of(pyramid, "ours", {30.0, 10.0, 20.0}, 0.004),
                   gp::bench::figures_of(pyramid, "chipmunk-default", {40.0, 50.0, 40.0}, 0.018),
                   gp::bench::figures_of(pyramid, "box2d-matched", {12.0, 8.0, 10.0}, 0.102),
                   gp::bench::figures_of(rain, "ours", {5.0}, -1.0),
                   gp::bench::figures_of(rain, "chipmunk-matched", {4.0}, -1.0)};
  table.engines = {"ours, settings", "chipmunk, settings", "box2d, settings"};
  table.repetitions = 3;
  table.seconds = 12.5;
  table.measured_at = "2026-11-22T14:00:00Z";
  return table;
}

TEST_CASE("The speed table gives medians, spreads and ratios of the given timings",
          "[NFR:Performance]") {
  const auto cells = gp::verification::speed_cells(fake_table());
  REQUIRE(cells.size() == 6);
  CHECK(cells[0] == Cells{"workload", "engine", "precision, build", "runs", "median [ms]",
                          "min [ms]", "max [ms]", "ours/engine", "below 1", "body-steps/s",
                          "watched body moved", "target (issue)"});
  // Medians 20, 40 and 10 ms: ours/chipmunk = 20/40, ours/box2d = 20/10; 4 bodies × 100 steps in
  // 20 ms are 2e4 body-steps/s.
  CHECK(cells[1] == Cells{"pyramid20", "ours", "double, this build", "3", "20.0", "10.0", "30.0",
                          "", "", "2e+04", "4 mm", "ours/peer < 1; top box moves < 3 cm"});
  CHECK(cells[2] == Cells{"", "chipmunk-default", "double, Debian build, debug checks on", "3",
                          "40.0", "40.0", "50.0", "0.50", "yes", "1e+04", "18 mm", ""});
  CHECK(cells[3] == Cells{"", "box2d-matched", "float, Debian build, asserts on", "3", "10.0",
                          "8.0", "12.0", "2.00", "no", "4e+04", "102 mm", ""});
  // 5 ms over 4 ms; 2 bodies × 50 steps in 5 ms.
  CHECK(cells[4] == Cells{"rain1000", "ours", "double, this build", "1", "5.0", "5.0", "5.0", "",
                          "", "2e+04", "", "ours/peer < 1"});
  CHECK(cells[5] == Cells{"", "chipmunk-matched", "double, Debian build, debug checks on", "1",
                          "4.0", "4.0", "4.0", "1.25", "no", "2.5e+04", "", ""});
  CHECK(gp::verification::speed_target("free10000") == "≥ 3e7 body-steps/s");
  CHECK(gp::verification::speed_target("rain4000").empty());
}

TEST_CASE("speed.json holds the same figures and how they were measured", "[NFR:Performance]") {
  const auto json = nlohmann::json::parse(gp::verification::speed_json(fake_table()));
  CHECK(json["command"] == "build/bin/gamephysics verify");
  CHECK(json["repetitions"] == 3);
  CHECK(json["engines"].size() == 3);
  REQUIRE(json["rows"].size() == 5);
  const auto& chipmunk = json["rows"][1];
  CHECK(chipmunk["engine"] == "chipmunk-default");
  CHECK(chipmunk["build"] == "double, Debian build, debug checks on");
  CHECK(chipmunk["median_ms"].get<double>() == Approx(40.0));
  CHECK(chipmunk["ours_over_engine"].get<double>() == Approx(0.5));
  CHECK(chipmunk["watched_body_moved_m"].get<double>() == Approx(0.018));
  CHECK(json["rows"][3].count("watched_body_moved_m") == 0);
}

TEST_CASE("The report shows the speed table, or says that --quick skipped it",
          "[NFR:Performance]") {
  const gp::verification::SpeedSection measured{fake_table(), ""};
  CHECK_THAT(
      gp::verification::speed_markdown(measured),
      Catch::Contains("|:---|:---|:---|---:|") &&
          Catch::Contains("|pyramid20|ours|double, this build|3|20.0|10.0|30.0|||2e+04|4 mm|") &&
          Catch::Contains("debug checks on") && Catch::Contains("- box2d, settings"));
  CHECK_THAT(gp::verification::speed_html(measured),
             Catch::Contains("<td>chipmunk-default</td><td>double, Debian build, debug checks "
                             "on</td><td>3</td><td>40.0</td>") &&
                 Catch::Contains("<code>build/bin/gamephysics verify</code>"));
  gp::verification::SuiteOptions quick;
  quick.quick = true;
  const auto skipped = gp::verification::speed_against_peers(quick);
  CHECK_FALSE(skipped.table);
  CHECK_THAT(gp::verification::speed_markdown(skipped),
             Catch::Contains("## speed against the peers") && Catch::Contains("--quick"));
}

}  // namespace test_speed_table
}  // namespace
