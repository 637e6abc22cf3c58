// The report of `gamephysics verify`: out/report/report.md and index.html with every check, the
// data as CSV beside them, and plots made by matplotlib (plots.py).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include "verification/html/html_escape.hpp"
#include "verification/markdown_cell.hpp"
#include "verification/suite/report.hpp"
#include "verification/suite/speed_report.hpp"

namespace gp::verification {

std::string figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

ReportSummary summarise(const std::vector<Check>& checks) {
  ReportSummary s;
  for (const Check& c : checks) {
    auto& section = s.sections[c.section];
    ++section.rows;
    if (c.criterion != "reported") ++section.checked;
    if (!c.passed) ++section.failed, s.failures.push_back(&c);
  }
  return s;
}

void write_report(const std::filesystem::path& out, const std::vector<Check>& checks,
                  const CsvFiles& data, const std::vector<std::string>& plots,
                  const SpeedSection& speed) {
  std::filesystem::create_directories(out / "data");
  for (const auto& [name, text] : data) std::ofstream(out / "data" / name) << text;
  if (speed.table) {
    std::ofstream(out / "speed.json") << speed_json(*speed.table);
  } else {
    std::filesystem::remove(out / "speed.json");
  }
  const ReportSummary summary = summarise(checks);
  std::ofstream md(out / "report.md");
  std::ofstream html(out / "index.html");
  md << "# GamePhysics verification report\n\nMade by `build/bin/gamephysics verify` (./run.sh); "
        "every SRS item with its equation, code, tests, checks and errata: "
        "[audit.html](audit.html). "
        "Every row names the SRS items it verifies; a row with a criterion passes or fails, a "
        "row marked \"reported\" gives figures only.\n\n## Summary\n\n"
        "|section|rows|with a criterion|failed|\n|:---|---:|---:|---:|\n";
  html << "<!doctype html><html><head><meta charset=\"utf-8\"><title>GamePhysics verification"
          "</title><style>body{font-family:sans-serif;margin:2em;max-width:80em}"
          "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:"
          "0.3em 0.6em;text-align:left}.fail{background:#fdd}.pass{background:#dfd}"
          "img{max-width:48%;margin:0.5%}</style></head><body>"
          "<h1>GamePhysics verification report</h1><p>Made by <code>build/bin/gamephysics "
          "verify</code>. Data: <a href=\"data/\">data/</a> (CSV). Also as <a href=\"report.md\">"
          "Markdown</a>. Every SRS item with its equation, code, tests, checks and errata: <a "
          "href=\"audit.html\">the audit "
          "page</a>.</p><h2>Summary</h2><table><tr><th>section</th><th>rows</th><th>with a "
          "criterion</th><th>failed</th></tr>";
  for (const auto& [name, s] : summary.sections) {
    md << "|" << name << "|" << s.rows << "|" << s.checked << "|" << s.failed << "|\n";
    html << "<tr class=\"" << (s.failed ? "fail" : "pass") << "\"><td>" << html_escape(name)
         << "</td><td>" << s.rows << "</td><td>" << s.checked << "</td><td>" << s.failed
         << "</td></tr>";
  }
  html << "</table>";
  std::string section;
  for (const Check& c : checks) {
    if (c.section != section) {
      section = c.section;
      md << "\n## " << section
         << "\n\n|check|SRS ids|measured|criterion|result|\n"
            "|:---|:---|:---|:---|:---|\n";
      html << (section.empty() ? "" : "</table>") << "<h2>" << html_escape(section)
           << "</h2><table><tr><th>check</th><th>SRS ids</th><th>measured</th><th>criterion"
              "</th><th>result</th></tr>";
    }
    const std::string result =
        c.criterion == "reported" ? "reported" : (c.passed ? "PASS" : "FAIL");
    md << "|" << markdown_cell(c.name) << "|" << c.srs_ids << "|" << markdown_cell(c.measured)
       << "|" << markdown_cell(c.criterion) << "|" << result << "|\n";
    html << "<tr class=\"" << (c.passed ? "" : "fail") << "\"><td>" << html_escape(c.name)
         << "</td><td>" << html_escape(c.srs_ids) << "</td><td>" << html_escape(c.measured)
         << "</td><td>" << html_escape(c.criterion) << "</td><td>" << result << "</td></tr>";
  }
  html << "</table>";
  md << speed_markdown(speed);
  html << speed_html(speed);
  if (!plots.empty()) {
    md << "\n## Plots\n\n";
    html << "<h2>Plots</h2>";
    for (const auto& p : plots) {
      md << "![" << p << "](" << p << ")\n";
      html << "<img src=\"" << p << "\" alt=\"" << p << "\">";
    }
  }
  html << "</body></html>\n";
}

std::vector<std::string> make_plots(const std::filesystem::path& script,
                                    const std::filesystem::path& out) {
  // Debian's python3 has python3-matplotlib; a python3 earlier on PATH (pyenv) may not.
  const std::string python =
      std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = python + " \"" + script.string() + "\" \"" + out.string() +
                              "\" > \"" + (out / "plots.log").string() + "\" 2>&1";
  std::vector<std::string> plots;
  if (std::system(command.c_str()) != 0) return plots;
  std::ifstream list(out / "plots.txt");
  for (std::string name; std::getline(list, name);) plots.push_back(name);
  return plots;
}

}  // namespace gp::verification
