#include "verification/suite/suite.hpp"

#include <iomanip>
#include <iostream>

#include "verification/suite/report.hpp"

namespace gp::verification {

SuiteResult run_suite(const SuiteOptions& o, const std::vector<Check>& audit_rows) {
  std::vector<Check> checks = audit_rows;
  const auto scenes = load_scenes(o.root / "scenes");
  CsvFiles data;
  const auto add = [&checks](const std::vector<Check>& rows) {
    checks.insert(checks.end(), rows.begin(), rows.end());
  };
  OracleReferences references;
  add(accuracy_checks(scenes, o, references, data));
  add(closed_form_checks(scenes, o));
  add(convergence_checks(scenes, o, data));
  add(conservation_checks(scenes, o));
  add(hard_case_checks(o));
  add(long_run_checks(o));
  add(peer_checks(scenes, o, references, data));
  add(pile_checks(scenes, o, data));
  add(stability_checks(o));
  if (!o.quick) add(work_precision_checks(scenes, o, data));
  add(criteria_level_checks(checks, o));
  const SpeedSection speed = speed_against_peers(o);
  write_report(o.out, checks, data, {}, speed);
  const auto plots = make_plots(o.root / "verification" / "suite" / "plots.py", o.out);
  write_report(o.out, checks, data, plots, speed);

  const ReportSummary summary = summarise(checks);
  std::ostream& out = o.progress ? *o.progress : std::cout;
  out << "\nVerification summary (" << (o.quick ? "quick" : "full") << "):\n";
  out << "  " << std::left << std::setw(34) << "section" << std::right << std::setw(6) << "rows"
      << std::setw(10) << "checked" << std::setw(8) << "failed\n";
  for (const auto& [name, s] : summary.sections) {
    out << "  " << std::left << std::setw(34) << name << std::right << std::setw(6) << s.rows
        << std::setw(10) << s.checked << std::setw(7) << s.failed << "\n";
  }
  for (const Check* c : summary.failures) {
    out << "  FAILED: " << c->section << ": " << c->name << ": " << c->measured
        << " (criterion: " << c->criterion << ")\n";
  }
  out << "  speed against the peers: "
      << (speed.table
              ? figure(speed.table->seconds) + " s, table in " + (o.out / "speed.json").string()
              : speed.why_not)
      << "\n";
  out << "  report: " << (o.out / "index.html").string() << " ("
      << (plots.empty() ? "no plots: see plots.log" : std::to_string(plots.size()) + " plots")
      << ")\n";
  out << "  result: " << (summary.failures.empty() ? "PASS" : "FAIL") << "\n";
  return {summary.failures.empty(), std::move(checks)};
}

}  // namespace gp::verification
