#include "verification/audit/audit_page.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "verification/html/html_escape.hpp"
#include "verification/traceability/trace_report.hpp"

namespace gp::verification {

namespace {

const char* kStyle =
    "body{font-family:sans-serif;margin:2em;max-width:90em;color:#222}"
    "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;padding:0.2em "
    "0.5em;text-align:left;vertical-align:top}.fail{background:#fdd}.pass{background:#dfd}"
    ".srs-item{border-top:2px solid #ddd;margin-top:1.5em}.srs-item h3{margin:0.5em 0}"
    ".equation{font-size:1.15em;margin:0.6em 0;overflow-x:auto}.label{color:#666}"
    "code{background:#f4f4f4;padding:0 0.2em}.matrix td{text-align:center;min-width:1.2em}"
    ".matrix th{font-size:0.8em}.matrix td:first-child{text-align:left;font-size:0.8em}"
    ".note{background:#ffe;border:1px solid #cc8;padding:0.5em}";

// The ids a check names, as its srs_ids field lists them: separated by spaces.
bool names(const Check& check, const std::string& id) {
  std::istringstream ids(check.srs_ids);
  for (std::string token; ids >> token;) {
    if (token == id) return true;
  }
  return false;
}

std::string tex(const std::string& source, bool display) {
  return std::string("<span class=\"") + (display ? "equation" : "tex") + "\" data-tex=\"" +
         html_escape(source) + "\">" + html_escape(source) + "</span>";
}

std::string check_table(const std::vector<Check>& checks, const std::string& id) {
  std::string html;
  int n = 0;
  for (const Check& c : checks) {
    if (!names(c, id)) continue;
    if (n++ == 0) {
      html +=
          "<table class=\"checks\"><tr><th>section</th><th>check</th><th>measured</th>"
          "<th>criterion</th><th>result</th></tr>";
    }
    const bool reported = c.criterion == "reported";
    html += std::string("<tr class=\"") +
            (reported   ? ""
             : c.passed ? "pass"
                        : "fail") +
            "\"><td>" + html_escape(c.section) + "</td><td>" + html_escape(c.name) + "</td><td>" +
            html_escape(c.measured) + "</td><td>" + html_escape(c.criterion) + "</td><td>" +
            (reported   ? "reported"
             : c.passed ? "PASS"
                        : "FAIL") +
            "</td></tr>";
  }
  return n ? html + "</table>" : std::string();
}

std::string tests_list(const TraceInputs& in, const AuditEvidence& evidence,
                       const std::string& id) {
  const auto tests = tests_of(in, id);
  const auto through_engine = tests_through_engine(in, id);
  if (tests.empty()) return "<p>Tests: none tagged with this id calls its function.</p>";
  const auto& results = evidence.test_results;
  std::string html = "<p>Catch2 test cases tagged <code>[" + html_escape(id) +
                     "]</code> that call its function" +
                     (results ? ", with their results:" : " (results: give --test-results)") +
                     "</p><ul class=\"tests\">";
  for (const TestCase* t : tests) {
    std::string result;
    if (results) {
      const auto passed = result_of(*results, t->name);
      result = !passed   ? "<span class=\"test-result\">not run</span> "
               : *passed ? "<span class=\"test-result pass\">PASS</span> "
                         : "<span class=\"test-result fail\">FAIL</span> ";
    }
    html += "<li>" + result + html_escape(t->name) + " <span class=\"label\">(" +
            html_escape(t->file) + ")</span></li>";
  }
  html += "</ul>";
  if (!through_engine.empty()) {
    html +=
        "<p>Exercised through the engine or the oracle (tagged <code>[via:" + html_escape(id) +
        "]</code>; not counted as testing the function): " + std::to_string(through_engine.size()) +
        " test cases.</p>";
  }
  return html;
}

std::string errata_list(const TraceInputs& in, const std::string& id) {
  std::string html;
  for (const Erratum& e : in.errata) {
    if (std::find(e.items.begin(), e.items.end(), id) == e.items.end()) continue;
    if (html.empty()) html = "<p>Errata (srs/errata.md):</p><ul class=\"errata\">";
    std::string shown;
    for (const auto& t : e.tests) shown += (shown.empty() ? "" : "; ") + t;
    html += "<li><strong>" + html_escape(e.id) + "</strong> (" + html_escape(e.kind) +
            "): " + html_escape(e.title) +
            (shown.empty() ? "" : ". Shown by: " + html_escape(shown)) + "</li>";
  }
  return html.empty() ? html : html + "</ul>";
}

std::string dimensions_table(const TraceInputs& in, const std::string& id) {
  std::string html;
  for (const DimensionalCheck& d : in.dimensions) {
    if (d.id != id) continue;
    if (html.empty()) {
      html =
          "<p>Dimensional check (Boost.Units, at compile time):</p><table class=\"dimensions\">"
          "<tr><th>form</th><th>equation</th><th>units</th><th>left side</th><th>right side"
          "</th><th>result</th></tr>";
    }
    std::string units;
    for (const auto& s : d.symbols)
      units += (units.empty() ? "" : ", ") + s.symbol + " [" + s.unit + "]";
    html += std::string("<tr class=\"") + (d.consistent ? "pass" : "fail") + "\"><td>" +
            html_escape(d.form) + "</td><td><code>" + html_escape(d.equation) + "</code></td><td>" +
            html_escape(units) + "</td><td>" + html_escape(d.lhs_dimension) + "</td><td>" +
            html_escape(d.rhs_dimension) + "</td><td>" +
            (d.consistent ? "consistent" : "inconsistent") + "</td></tr>";
  }
  return html.empty() ? html : html + "</table>";
}

std::string functions_paragraph(const TraceInputs& in, const std::string& id) {
  std::string html;
  for (const auto& r : in.registrations) {
    if (r.id != id) continue;
    std::string uses;
    for (const auto& u : r.uses) uses += (uses.empty() ? "" : ", ") + u;
    html += "<p>C++: <code>" + html_escape(r.function) + "</code> in <code>" + html_escape(r.file) +
            "</code>" + (uses.empty() ? "" : "; calls the models of " + html_escape(uses)) + "</p>";
  }
  return html.empty() ? "<p>C++: no function registered for this id.</p>" : html;
}

std::string model_section(const TraceInputs& in, const AuditEvidence& evidence, const Model& m,
                          const nlohmann::json& entry) {
  std::string html = "<section class=\"srs-item model\" id=\"" + html_escape(m.id) +
                     "\" data-id=\"" + html_escape(m.id) + "\"><h3>" + html_escape(m.id) + ": " +
                     html_escape(m.label) + "</h3><div>" + tex(m.equation, true) + "</div>";
  if (entry.contains("symbols") && entry["symbols"].is_array() && !entry["symbols"].empty()) {
    html += "<table class=\"symbols\"><tr><th>symbol</th><th>meaning</th><th>unit</th></tr>";
    for (const auto& s : entry["symbols"]) {
      html += "<tr><td>" + tex(s.value("symbol", ""), false) + "</td><td>" +
              html_escape(s.value("description", "")) + "</td><td>" +
              html_escape(s["unit"].is_string() ? s["unit"].get<std::string>() : "") + "</td></tr>";
    }
    html += "</table>";
  }
  if (entry.contains("uses") && entry["uses"].is_array() && !entry["uses"].empty()) {
    std::string uses;
    for (const auto& u : entry["uses"]) uses += (uses.empty() ? "" : ", ") + u.get<std::string>();
    html += "<p>The SRS says it uses: " + html_escape(uses) + "</p>";
  }
  html += functions_paragraph(in, m.id) + tests_list(in, evidence, m.id) +
          check_table(evidence.checks, m.id) + dimensions_table(in, m.id) + errata_list(in, m.id);
  return html + "</section>";
}

std::string item_section(const TraceInputs& in, const AuditEvidence& evidence, const Item& item) {
  return "<section class=\"srs-item\" id=\"" + html_escape(item.id) + "\" data-id=\"" +
         html_escape(item.id) + "\"><h3>" + html_escape(item.id) + "</h3><p>" +
         html_escape(item.text) + "</p>" + tests_list(in, evidence, item.id) +
         check_table(evidence.checks, item.id) + errata_list(in, item.id) + "</section>";
}

// One row per model, linking to its section: the overview an auditor starts from.
std::string index_table(const TraceInputs& in, const AuditEvidence& evidence) {
  std::string html =
      "<h2>Index</h2><table id=\"index\"><tr><th>SRS id</th><th>label</th><th>C++ function</th>"
      "<th>tests</th><th>checks of the suite</th><th>dimensions as written</th><th>errata</th>"
      "</tr>";
  for (const Model& m : in.catalog.models) {
    std::string function;
    for (const auto& r : in.registrations) {
      if (r.id == m.id) function = r.function;
    }
    const auto tests = tests_of(in, m.id);
    std::string tested = std::to_string(tests.size());
    if (const auto& results = evidence.test_results) {
      int failed = 0;
      for (const TestCase* t : tests) failed += result_of(*results, t->name) == false ? 1 : 0;
      tested += failed ? ", " + std::to_string(failed) + " FAILED" : ", all pass";
    }
    int checks = 0, failed_checks = 0;
    for (const Check& c : evidence.checks) {
      if (names(c, m.id)) ++checks, failed_checks += c.passed ? 0 : 1;
    }
    std::string dimensions;
    for (const DimensionalCheck& d : in.dimensions) {
      if (d.id == m.id && d.form == "as written") dimensions = d.consistent ? "consistent" : "not";
    }
    std::string errata;
    for (const Erratum& e : in.errata) {
      if (std::find(e.items.begin(), e.items.end(), m.id) != e.items.end()) {
        errata += (errata.empty() ? "" : " ") + e.id;
      }
    }
    html += "<tr><td><a href=\"#" + html_escape(m.id) + "\">" + html_escape(m.id) +
            "</a></td><td>" + html_escape(m.label) + "</td><td><code>" + html_escape(function) +
            "</code></td><td>" + tested + "</td><td>" + std::to_string(checks) +
            (failed_checks ? ", " + std::to_string(failed_checks) + " FAILED" : "") +
            "</td><td class=\"" + (dimensions == "consistent" ? "pass" : "fail") + "\">" +
            dimensions + "</td><td>" + html_escape(errata) + "</td></tr>";
  }
  return html + "</table>";
}

// A matrix of traceability/ (its CSV: a header of columns, then one row per item) as a table,
// under the title and legend of its Markdown.
std::string matrix_table(const TraceFiles& files, const std::string& name) {
  std::istringstream md(files.at(name + ".md"));
  std::string title, blank, legend;
  std::getline(md, title);
  std::getline(md, blank);
  std::getline(md, legend);
  std::string html = "<h3>" + html_escape(title.substr(title.find(' ') + 1)) + "</h3><p>" +
                     html_escape(legend) + " (<code>traceability/" + name +
                     ".md</code>)</p><table class=\"matrix\" id=\"matrix-" + name + "\">";
  std::istringstream csv(files.at(name + ".csv"));
  bool header = true;
  for (std::string line; std::getline(csv, line); header = false) {
    html += "<tr>";
    std::istringstream cells(line + ",");
    for (std::string cell; std::getline(cells, cell, ',');) {
      html += (header ? "<th>" : "<td>") + html_escape(cell) + (header ? "</th>" : "</td>");
    }
    html += "</tr>";
  }
  return html + "</table>";
}

std::string katex_script(const std::optional<KatexInline>& katex) {
  if (!katex) return "";
  // throwOnError false: a formula KaTeX cannot parse is shown in red (.katex-error), not lost.
  return "<script>" + katex->js +
         "</script><script>for(const el of document.querySelectorAll('[data-tex]'))"
         "katex.render(el.dataset.tex,el,{displayMode:el.classList.contains('equation'),"
         "throwOnError:false,strict:'ignore'});</script>";
}

}  // namespace

void write_audit_page(std::ostream& out, const SrsAudit& audit, const AuditEvidence& evidence,
                      const std::optional<KatexInline>& katex) {
  const std::vector<Check>& checks = evidence.checks;
  const TraceInputs& in = audit.inputs;
  const Catalog& c = in.catalog;
  out << "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>GamePhysics: SRS "
         "audit</title><style>"
      << kStyle << (katex ? katex->css : "") << "</style></head><body><h1>GamePhysics: the SRS "
      << "audit</h1><p>Every item of the SRS catalogue (<code>srs/catalog.json</code>, "
      << c.all_ids().size() << " items) with its equation, the C++ function that implements it, "
      << "the tests tagged with its id, the verification checks that name it and their results, "
      << "its dimensional check and its errata. Made by <code>gamephysics "
      << (checks.empty() ? "audit" : "verify")
      << "</code>"
      // `audit` alone writes no report beside the page, so nothing to link to.
      << (checks.empty() ? "" : "; the full report is <a href=\"index.html\">index.html</a>")
      << ".</p>";
  if (!katex) {
    out << "<p class=\"note\" id=\"no-katex\">KaTeX is not installed, so the equations are shown "
           "as LaTeX source: run <code>tools/install-web.sh</code> and write the page again.</p>";
  } else {
    out << "<p class=\"label\">Equations rendered by KaTeX " << html_escape(katex->version)
        << ", inlined.</p>";
  }
  out << "<p>Audit: " << (audit.passed() ? "every traceability check passes" : "FAILED")
      << "; checks of the suite: " << (checks.empty() ? "not run (gamephysics audit)" : "below")
      << ".</p>";
  for (const auto& p : audit.result.problems)
    out << "<p class=\"fail\">" << html_escape(p) << "</p>";
  if (const auto& results = evidence.test_results) {
    int passed = 0, failed = 0, missing = 0;
    for (const TestCase& t : in.tests) {
      const auto result = result_of(*results, t.name);
      if (!result)
        ++missing;
      else if (*result)
        ++passed;
      else
        ++failed;
    }
    out << "<p id=\"test-summary\">Catch2 test cases of tests/: " << passed << " passed, " << failed
        << " failed, " << missing << " not in the test report.</p>";
  }

  out << index_table(in, evidence);
  static const std::pair<const char*, const char*> kModelKinds[] = {
      {"theoretical_models", "Theoretical models"},
      {"general_definitions", "General definitions"},
      {"data_definitions", "Data definitions"},
      {"instance_models", "Instance models"}};
  for (const auto& [key, heading] : kModelKinds) {
    out << "<h2>" << heading << "</h2>";
    for (const auto& entry : c.json[key]) {
      const std::string id = entry["id"];
      const auto m = std::find_if(c.models.begin(), c.models.end(),
                                  [&id](const Model& model) { return model.id == id; });
      out << model_section(in, evidence, *m, entry);
    }
  }
  const std::pair<const char*, const std::vector<Item>*> kItems[] = {
      {"Goals", &c.goals},
      {"Assumptions", &c.assumptions},
      {"Functional requirements", &c.functional_requirements},
      {"Non-functional requirements", &c.nonfunctional_requirements},
      {"Likely changes", &c.likely_changes},
      {"Unlikely changes", &c.unlikely_changes}};
  for (const auto& [heading, items] : kItems) {
    out << "<h2>" << heading << "</h2>";
    for (const Item& item : *items) out << item_section(in, evidence, item);
  }
  const TraceFiles files = render_traceability(in, audit.result);
  out << "<h2>Traceability matrices</h2>";
  for (const char* name : {"assumptions_vs_assumptions", "assumptions_vs_items", "items_vs_items",
                           "requirements_vs_items"}) {
    out << matrix_table(files, name);
  }
  out << katex_script(katex) << "</body></html>\n";
}

std::filesystem::path write_audit_page(const std::filesystem::path& root,
                                       const std::filesystem::path& out_dir, const SrsAudit& audit,
                                       const AuditEvidence& evidence) {
  std::filesystem::create_directories(out_dir);
  const auto file = out_dir / "audit.html";
  std::ofstream out(file);
  write_audit_page(out, audit, evidence,
                   load_katex(root / "tools" / "web" / "node_modules" / "katex"));
  return file;
}

}  // namespace gp::verification
