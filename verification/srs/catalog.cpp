#include "verification/srs/catalog.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace gp::verification {

namespace {

std::vector<Item> items(const nlohmann::json& list) {
  std::vector<Item> result;
  for (const auto& entry : list) result.push_back({entry.at("id"), entry.at("text")});
  return result;
}

std::vector<Edge> edges(const nlohmann::json& list) {
  std::vector<Edge> result;
  for (const auto& pair : list) result.emplace_back(pair.at(0), pair.at(1));
  return result;
}

}  // namespace

std::vector<std::string> Catalog::all_ids() const {
  std::vector<std::string> ids;
  auto add = [&ids](const auto& list) {
    for (const auto& entry : list) ids.push_back(entry.id);
  };
  add(goals);
  add(assumptions);
  add(models);
  add(functional_requirements);
  add(nonfunctional_requirements);
  add(likely_changes);
  add(unlikely_changes);
  return ids;
}

bool Catalog::contains(const std::string& id) const {
  const auto ids = all_ids();
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

Catalog load_catalog(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open the SRS catalogue");
  Catalog catalog;
  try {
    catalog.json = nlohmann::json::parse(in);
    const auto& j = catalog.json;
    catalog.goals = items(j.at("goals"));
    catalog.assumptions = items(j.at("assumptions"));
    for (const char* section :
         {"theoretical_models", "general_definitions", "data_definitions", "instance_models"}) {
      for (const auto& m : j.at(section)) {
        catalog.models.push_back({m.at("id"), m.at("kind"), m.at("label"), m.at("equation")});
      }
    }
    catalog.functional_requirements = items(j.at("functional_requirements"));
    catalog.nonfunctional_requirements = items(j.at("nonfunctional_requirements"));
    catalog.likely_changes = items(j.at("likely_changes"));
    catalog.unlikely_changes = items(j.at("unlikely_changes"));
    catalog.input_constraints = j.at("input_constraints").size();
    catalog.output_constraints = j.at("output_constraints").size();
    const auto& trace = j.at("traceability");
    catalog.assumptions_vs_assumptions = edges(trace.at("assumptions_vs_assumptions"));
    catalog.assumptions_vs_items = edges(trace.at("assumptions_vs_items"));
    catalog.items_vs_items = edges(trace.at("items_vs_items"));
    catalog.requirements_vs_items = edges(trace.at("requirements_vs_items"));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  return catalog;
}

}  // namespace gp::verification
