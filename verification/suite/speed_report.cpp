#include "verification/suite/speed_report.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

#include "verification/bench/bench_engine.hpp"
#include "verification/html/html_escape.hpp"

namespace gp::verification {

namespace {

constexpr const char* kHeading = "speed against the peers";

// What the figures are, in either format (Markdown's backticks become <code> in HTML).
std::string method(const SpeedTable& t) {
  std::ostringstream text;
  text << "Wall time of one whole run in ms (set-up left out) of each workload of "
          "verification/bench, "
       << t.repetitions
       << " runs in each engine, alternately (ours, then each peer, then ours again, …) so that "
          "a slow phase of the machine hits all alike. Each peer runs twice: \"default\" as its "
          "users run it (its own collision handlers, slop, restitution threshold, iterations and "
          "sleeping: Chipmunk2D multiplies the surfaces' coefficients, keeps slop 0.1 and never "
          "sleeps; Box2D sleeps), and \"matched\" to our physics (our combining rule, by a "
          "Chipmunk2D pre-solve callback on every contact, our slop, threshold and iteration "
          "counts, sleeping off). Both peers step with symplectic Euler and run all their "
          "iterations; ours steps with velocity Verlet and ends its velocity passes early once a "
          "pass changes no velocity by more than its tolerance. Debian's Chipmunk2D runs with "
          "its debug checks on and Debian's Box2D with its asserts on (neither was built with "
          "NDEBUG), which makes them slower than release builds. A measurement, not a check: "
          "\"below 1\" says whether ours is faster, and the targets of the issue "
          "(NFR:Performance) stand beside. "
          "Measured at "
       << t.measured_at << " in " << figure(t.seconds)
       << " s; the same table in speed.json. Reproduce: `build/bin/gamephysics verify`.";
  return text.str();
}

std::string code_to_html(const std::string& text) {
  std::string out;
  bool open = false;
  for (char c : html_escape(text)) {
    if (c != '`') {
      out += c;
      continue;
    }
    out += open ? "</code>" : "<code>";
    open = !open;
  }
  return out;
}

}  // namespace

std::string speed_markdown(const SpeedSection& section) {
  std::ostringstream md;
  md << "\n## " << kHeading << "\n\n";
  if (!section.table) {
    md << section.why_not << "\n";
    return md.str();
  }
  md << method(*section.table) << "\n\nEngines:\n\n";
  for (const std::string& engine : section.table->engines) md << "- " << engine << "\n";
  md << "\n";
  bool header = true;
  for (const auto& row : speed_cells(*section.table)) {
    md << "|";
    for (const std::string& cell : row) md << cell << "|";
    md << "\n";
    if (header) {
      md << "|:---|:---|:---|";
      for (std::size_t i = 3; i + 1 < row.size(); ++i) md << "---:|";
      md << ":---|\n";
      header = false;
    }
  }
  return md.str();
}

std::string speed_html(const SpeedSection& section) {
  std::ostringstream html;
  html << "<h2>" << kHeading << "</h2>";
  if (!section.table) {
    html << "<p>" << code_to_html(section.why_not) << "</p>";
    return html.str();
  }
  html << "<p>" << code_to_html(method(*section.table)) << "</p><p>Engines:</p><ul>";
  for (const std::string& engine : section.table->engines) {
    html << "<li>" << html_escape(engine) << "</li>";
  }
  html << "</ul><table>";
  const char* tag = "th";
  for (const auto& row : speed_cells(*section.table)) {
    html << "<tr>";
    for (const std::string& cell : row) {
      html << "<" << tag << ">" << html_escape(cell) << "</" << tag << ">";
    }
    html << "</tr>";
    tag = "td";
  }
  html << "</table>";
  return html.str();
}

std::string speed_json(const SpeedTable& t) {
  nlohmann::ordered_json json;
  json["command"] = "build/bin/gamephysics verify";
  json["measured_at"] = t.measured_at;
  json["section_seconds"] = t.seconds;
  json["repetitions"] = t.repetitions;
  json["engines"] = t.engines;
  json["rows"] = nlohmann::ordered_json::array();
  for (const bench::Figures& f : t.figures) {
    nlohmann::ordered_json row{{"workload", f.workload},
                               {"engine", f.engine},
                               {"build", std::string(bench::engine_build(f.engine))},
                               {"runs", f.repetitions},
                               {"median_ms", f.median_ms},
                               {"min_ms", f.min_ms},
                               {"max_ms", f.max_ms},
                               {"stddev_ms", f.stddev_ms},
                               {"body_steps_per_s", f.body_steps_per_s}};
    if (const auto ratio = bench::ours_over_engine(t.figures, f)) row["ours_over_engine"] = *ratio;
    if (f.moved_m >= 0.0) row["watched_body_moved_m"] = f.moved_m;
    if (const std::string target = speed_target(f.workload); !target.empty()) {
      row["target"] = target;
    }
    json["rows"].push_back(std::move(row));
  }
  return json.dump(2) + "\n";
}

}  // namespace gp::verification
