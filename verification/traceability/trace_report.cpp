#include "verification/traceability/trace_report.hpp"

#include <algorithm>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "verification/markdown_cell.hpp"

namespace gp::verification {

namespace {

std::vector<std::string> ids(const std::vector<Item>& list) {
  std::vector<std::string> result;
  for (const auto& item : list) result.push_back(item.id);
  return result;
}

std::vector<std::string> model_ids(const Catalog& catalog) {
  std::vector<std::string> result;
  for (const auto& m : catalog.models) result.push_back(m.id);
  return result;
}

std::vector<std::string> concat(std::initializer_list<std::vector<std::string>> lists) {
  std::vector<std::string> result;
  for (const auto& list : lists) result.insert(result.end(), list.begin(), list.end());
  return result;
}

// A matrix as both Markdown and CSV; `mark(row, column)` gives the cell text.
struct Matrix {
  std::string title;
  std::string legend;
  std::vector<std::string> rows;
  std::vector<std::string> columns;
  std::function<std::string(const std::string&, const std::string&)> mark;

  std::string csv() const {
    std::string text = "item";
    for (const auto& c : columns) text += "," + c;
    text += "\n";
    for (const auto& r : rows) {
      text += r;
      for (const auto& c : columns) text.append(",").append(mark(r, c));
      text += "\n";
    }
    return text;
  }

  std::string markdown() const {
    std::string text = "# " + title + "\n\n" + legend + "\n\n|";
    for (const auto& c : columns) text += "|" + c;
    text += "|\n|:---";
    for (std::size_t i = 0; i < columns.size(); ++i) text += "|:-:";
    text += "|\n";
    for (const auto& r : rows) {
      text += "|" + r;
      for (const auto& c : columns) text.append("|").append(mark(r, c));
      text += "|\n";
    }
    return text;
  }
};

std::function<std::string(const std::string&, const std::string&)> marks_of(
    const std::vector<Edge>& edges) {
  const std::set<Edge> set(edges.begin(), edges.end());
  return [set](const std::string& row, const std::string& column) {
    return set.count({row, column}) ? std::string("X") : std::string();
  };
}

void add(TraceFiles& files, const std::string& name, const Matrix& matrix) {
  files[name + ".md"] = matrix.markdown();
  files[name + ".csv"] = matrix.csv();
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string status_name(EdgeStatus status) {
  switch (status) {
    case EdgeStatus::matched:
      return "matched";
    case EdgeStatus::srs_only:
      return "SRS only";
    case EdgeStatus::code_only:
      return "code only";
  }
  return "";
}

void add_items(TraceFiles& files, const TraceInputs& in) {
  std::string md =
      "# SRS item -> function -> tests\n\nEach theoretical model, general definition, data "
      "definition and instance model, the C++ function that implements it (as its registration "
      "declares) and the Catch2 test cases tagged with its id whose body calls the function "
      "(directly or "
      "through the models that call it).\n\n"
      "|SRS id|label|function|file|tests|\n|:---|:---|:---|:---|:---|\n";
  std::string csv = "id,label,function,file,tests\n";
  for (const auto& model : in.catalog.models) {
    std::string function, file;
    for (const auto& r : in.registrations) {
      if (r.id == model.id) function = r.function, file = r.file;
    }
    std::vector<std::string> names;
    for (const auto* t : tests_of(in, model.id)) names.push_back(t->file + ": " + t->name);
    std::string md_tests, csv_tests;
    for (const auto& n : names) {
      md_tests += (md_tests.empty() ? "" : "<br>") + n;
      csv_tests += (csv_tests.empty() ? "" : "; ") + n;
    }
    md +=
        "|" + model.id + "|" + model.label + "|`" + function + "`|" + file + "|" + md_tests + "|\n";
    csv += csv_field(model.id) + "," + csv_field(model.label) + "," + csv_field(function) + "," +
           csv_field(file) + "," + csv_field(csv_tests) + "\n";
  }
  files["items.md"] = md;
  files["items.csv"] = csv;
}

void add_edges(TraceFiles& files, const TraceResult& result) {
  std::string md =
      "# Model-to-model edges: SRS against code\n\nAn edge FROM -> TO means FROM uses TO. The "
      "SRS's edges come from its table TraceMatRefvsRef; the code's from each function's "
      "registration, which the check compares with the calls in the function's file. Every "
      "difference is explained by an erratum in srs/errata.md.\n\n"
      "|from|to|status|erratum|\n|:---|:---|:---|:---|\n";
  std::string csv = "from,to,status,erratum\n";
  for (const auto& row : result.edges) {
    md += "|" + row.edge.first + "|" + row.edge.second + "|" + status_name(row.status) + "|" +
          row.erratum + "|\n";
    csv += row.edge.first + "," + row.edge.second + "," + status_name(row.status) + "," +
           row.erratum + "\n";
  }
  files["edges.md"] = md;
  files["edges.csv"] = csv;
}

void add_dimensions(TraceFiles& files, const TraceInputs& in) {
  std::string md =
      "# Dimensional audit\n\nEach SRS equation with the units its symbols have in the SRS (as "
      "written, verification/dimensions/dimensional_audit.cpp), then each model function of "
      "models/ instantiated with Boost.Units quantities of the units its doc comment gives (in the "
      "code, verification/dimensions/code_audit.cpp): a model function with a dimensional slip "
      "does not compile. Vectors are (x, y); the radian is the SI unit 1.\n\n"
      "|SRS id|form|equation|units|left side|right side|result|\n"
      "|:---|:---|:---|:---|:---|:---|:---|\n";
  std::string csv = "id,form,equation,units,lhs,rhs,consistent\n";
  for (const auto& d : in.dimensions) {
    std::string units;
    for (const auto& s : d.symbols)
      units += (units.empty() ? "" : " ") + s.symbol + "[" + s.unit + "]";
    const std::string result = d.consistent ? "consistent" : "INCONSISTENT";
    md += "|" + d.id + "|" + d.form + "|`" + markdown_cell(d.equation) + "`|" +
          markdown_cell(units) + "|" + d.lhs_dimension + "|" + d.rhs_dimension + "|" + result +
          "|\n";
    csv += csv_field(d.id) + "," + csv_field(d.form) + "," + csv_field(d.equation) + "," +
           csv_field(units) + "," + csv_field(d.lhs_dimension) + "," + csv_field(d.rhs_dimension) +
           "," + (d.consistent ? "true" : "false") + "\n";
  }
  files["dimensions.md"] = md;
  files["dimensions.csv"] = csv;
}

}  // namespace

TraceFiles render_traceability(const TraceInputs& in, const TraceResult& result) {
  const Catalog& c = in.catalog;
  TraceFiles files;
  const auto assumptions = ids(c.assumptions);
  const auto models = model_ids(c);
  const auto requirements =
      concat({ids(c.functional_requirements), ids(c.nonfunctional_requirements)});
  const std::string x_legend = "X: the row depends on the column, as the SRS declares.";
  add(files, "assumptions_vs_assumptions",
      {"Assumptions against assumptions", x_legend, assumptions, assumptions,
       marks_of(c.assumptions_vs_assumptions)});
  add(files, "assumptions_vs_items",
      {"Items against assumptions", x_legend,
       concat({models, requirements, ids(c.likely_changes), ids(c.unlikely_changes)}), assumptions,
       marks_of(c.assumptions_vs_items)});
  std::map<Edge, EdgeStatus> status;
  for (const auto& row : result.edges) status[row.edge] = row.status;
  add(files, "items_vs_items",
      {"Models against models",
       "X: the row uses the column, in the SRS and in the code. S: in the SRS only. C: in the "
       "code only (see edges.md for the erratum that explains each S and C).",
       models, models, [status](const std::string& row, const std::string& column) {
         const auto found = status.find({row, column});
         if (found == status.end()) return std::string();
         return std::string(found->second == EdgeStatus::matched    ? "X"
                            : found->second == EdgeStatus::srs_only ? "S"
                                                                    : "C");
       }});
  add(files, "requirements_vs_items",
      {"Requirements and goals against items", x_legend, concat({ids(c.goals), requirements}),
       concat({models, requirements}), marks_of(c.requirements_vs_items)});
  add_items(files, in);
  add_edges(files, result);
  add_dimensions(files, in);
  return files;
}

void write_traceability(const TraceFiles& files, const std::filesystem::path& directory) {
  std::filesystem::create_directories(directory);
  for (const auto& [name, content] : files) {
    std::ofstream(directory / name, std::ios::binary) << content;
  }
}

std::vector<std::string> stale_traceability(const TraceFiles& files,
                                            const std::filesystem::path& directory) {
  std::vector<std::string> stale;
  for (const auto& [name, content] : files) {
    std::ifstream in(directory / name, std::ios::binary);
    std::stringstream committed;
    committed << in.rdbuf();
    if (!in || committed.str() != content) stale.push_back(name);
  }
  return stale;
}

}  // namespace gp::verification
