#include "verification/traceability/traceability.hpp"

#include <algorithm>
#include <set>

#include "verification/traceability/code_edges.hpp"
#include "verification/traceability/test_calls.hpp"

namespace gp::verification {

namespace {

// Marks a test that exercises a model only through the engine or the oracle: it is listed with
// the model but does not count as testing its function.
constexpr std::string_view kVia = "via:";

std::string join(const std::vector<std::string>& parts) {
  std::string text;
  for (const auto& part : parts) text += (text.empty() ? "" : ", ") + part;
  return "{" + text + "}";
}

std::string explaining_erratum(const TraceInputs& inputs, const Edge& edge) {
  for (const auto& e : inputs.errata) {
    if (std::find(e.edges.begin(), e.edges.end(), edge) != e.edges.end()) return e.id;
  }
  return "";
}

std::string function_of(const TraceInputs& in, const std::string& id) {
  for (const auto& r : in.registrations) {
    if (r.id == id) return r.function;
  }
  return "";
}

bool calls(const TraceInputs& in, const TestCase& test, const std::string& id) {
  const auto found = in.test_calls.find(test.name);
  return found != in.test_calls.end() && found->second.count(id) > 0;
}

void check_functions_and_tests(const TraceInputs& in, std::vector<std::string>& problems) {
  for (const auto& model : in.catalog.models) {
    const auto count = std::count_if(in.registrations.begin(), in.registrations.end(),
                                     [&](const auto& r) { return r.id == model.id; });
    if (count == 0) problems.push_back(model.id + ": no function registers this model");
    if (count > 1) problems.push_back(model.id + ": registered by more than one function");
    const std::string function = function_of(in, model.id);
    if (tagged_tests(in, model.id).empty()) {
      problems.push_back(model.id + ": no test is tagged with it");
    } else if (tests_of(in, model.id).empty()) {
      problems.push_back(model.id + ": no test tagged with it calls " + function);
    } else if (passing_tests_of(in, model.id).empty()) {
      problems.push_back(model.id + ": no test that calls " + function + " passed");
    }
  }
  // A test tagged with a model claims to test its function, unless it is about the SRS's text.
  for (const auto& test : in.tests) {
    if (std::find(test.tags.begin(), test.tags.end(), "srs") != test.tags.end()) continue;
    for (const auto& tag : test.tags) {
      const std::string function = function_of(in, tag);
      if (!function.empty() && !calls(in, test, tag)) {
        problems.push_back(test.file + ": test \"" + test.name + "\" is tagged " + tag +
                           " but does not call " + function);
      }
    }
  }
  for (const auto& r : in.registrations) {
    if (!in.catalog.contains(r.id)) {
      problems.push_back(r.function + ": registers " + r.id + ", which is not in the SRS");
    }
    auto declared = r.uses;
    std::sort(declared.begin(), declared.end());
    const auto found = in.calls.find(r.id);
    const auto called = found == in.calls.end() ? std::vector<std::string>{} : found->second;
    if (declared != called) {
      problems.push_back(r.function + ": registers uses " + join(declared) + " but " + r.file +
                         " calls " + join(called));
    }
  }
  for (const auto& test : in.tests) {
    // catch_discover_tests hands names to CMake lists, which split on ';' and group on brackets.
    if (test.name.find_first_of("[];") != std::string::npos) {
      problems.push_back(test.file + ": test \"" + test.name +
                         "\" has '[', ']' or ';' in its name, which ctest cannot register");
    }
    for (const auto& tag : test.tags) {
      const std::string id = tag.starts_with(kVia) ? tag.substr(kVia.size()) : tag;
      if (id.find(':') != std::string::npos && !in.catalog.contains(id)) {
        problems.push_back(test.file + ": test \"" + test.name + "\" is tagged " + tag +
                           ", which is not in the SRS");
      }
    }
  }
}

std::vector<EdgeRow> compare_edges(const TraceInputs& in, std::vector<std::string>& problems) {
  const std::set<Edge> srs(in.catalog.items_vs_items.begin(), in.catalog.items_vs_items.end());
  std::set<Edge> code;
  for (const auto& r : in.registrations) {
    for (const auto& used : r.uses) code.emplace(r.id, used);
  }
  std::set<Edge> all = srs;
  all.insert(code.begin(), code.end());
  std::vector<EdgeRow> rows;
  for (const auto& edge : all) {
    const bool in_srs = srs.count(edge) > 0, in_code = code.count(edge) > 0;
    const EdgeStatus status = in_srs && in_code ? EdgeStatus::matched
                              : in_srs          ? EdgeStatus::srs_only
                                                : EdgeStatus::code_only;
    std::string erratum;
    if (status != EdgeStatus::matched) {
      erratum = explaining_erratum(in, edge);
      if (erratum.empty()) {
        problems.push_back("edge " + edge.first + " -> " + edge.second +
                           (in_srs ? " is declared by the SRS but not used by the code"
                                   : " is used by the code but not declared by the SRS") +
                           ", and no erratum explains it");
      }
    }
    rows.push_back({edge, status, erratum});
  }
  return rows;
}

void check_errata(const TraceInputs& in, std::vector<std::string>& problems) {
  std::set<std::string> test_names;
  for (const auto& t : in.tests) test_names.insert(t.name);
  for (const auto& e : in.errata) {
    for (const auto& id : e.items) {
      if (!in.catalog.contains(id)) problems.push_back(e.id + ": names " + id + ", not in the SRS");
    }
    if (e.tests.empty()) problems.push_back(e.id + ": names no test that shows it");
    for (const auto& name : e.tests) {
      if (!test_names.count(name)) problems.push_back(e.id + ": no test is named \"" + name + "\"");
    }
  }
  for (const auto& c : in.citations) {
    const bool exists = std::any_of(in.errata.begin(), in.errata.end(),
                                    [&](const Erratum& e) { return e.id == c.id; });
    if (!exists) {
      problems.push_back(c.file + ":" + std::to_string(c.line) + ": cites " + c.id +
                         ", which srs/errata.md does not have");
    }
  }
}

void check_dimensions(const TraceInputs& in, std::vector<std::string>& problems) {
  std::set<std::string> failing, checked, documented;
  for (const auto& d : in.dimensions) {
    if (d.form == "as written") {
      checked.insert(d.id);
      if (!d.consistent) failing.insert(d.id);
    } else if (!d.consistent) {
      problems.push_back(d.id + ": the implemented equation " + d.equation +
                         " is dimensionally inconsistent");
    }
  }
  for (const auto& e : in.errata) {
    if (e.kind == "dimension") documented.insert(e.items.begin(), e.items.end());
  }
  for (const auto& model : in.catalog.models) {
    if (!checked.count(model.id)) problems.push_back(model.id + ": no dimensional check");
  }
  for (const auto& id : failing) {
    if (!documented.count(id)) {
      problems.push_back(id + ": fails the dimensional audit but has no erratum of kind dimension");
    }
  }
  for (const auto& id : documented) {
    if (!failing.count(id)) {
      problems.push_back(id + ": has a dimension erratum but passes the dimensional audit");
    }
  }
}

}  // namespace

TraceInputs gather_trace_inputs(const std::filesystem::path& root) {
  TraceInputs in;
  in.catalog = load_catalog(root / "srs" / "catalog.json");
  in.registrations = models::registrations();
  in.calls = called_models(root, in.registrations);
  in.tests = index_tests(root, root / "tests");
  for (const auto& t : in.tests) in.test_calls[t.name] = models_called(t.body, in.registrations);
  in.errata = load_errata(root / "srs" / "errata.md");
  in.citations = erratum_citations(root);
  in.dimensions = dimensional_audit();
  return in;
}

std::vector<const TestCase*> tagged_tests(const TraceInputs& inputs, const std::string& id) {
  std::vector<const TestCase*> found;
  for (const auto& t : inputs.tests) {
    if (std::find(t.tags.begin(), t.tags.end(), id) != t.tags.end()) found.push_back(&t);
  }
  return found;
}

std::vector<const TestCase*> tests_of(const TraceInputs& inputs, const std::string& id) {
  auto found = tagged_tests(inputs, id);
  std::erase_if(found, [&](const TestCase* t) { return !calls(inputs, *t, id); });
  return found;
}

std::vector<const TestCase*> tests_through_engine(const TraceInputs& inputs,
                                                  const std::string& id) {
  return tagged_tests(inputs, std::string(kVia) + id);
}

std::vector<const TestCase*> passing_tests_of(const TraceInputs& inputs, const std::string& id) {
  auto found = tests_of(inputs, id);
  if (inputs.results) {
    std::erase_if(found,
                  [&](const TestCase* t) { return result_of(*inputs.results, t->name) != true; });
  }
  return found;
}

TraceResult analyse(const TraceInputs& inputs) {
  TraceResult result;
  check_functions_and_tests(inputs, result.problems);
  result.edges = compare_edges(inputs, result.problems);
  check_errata(inputs, result.problems);
  check_dimensions(inputs, result.problems);
  return result;
}

}  // namespace gp::verification
