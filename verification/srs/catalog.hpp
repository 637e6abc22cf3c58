#pragma once
// srs/catalog.json, the SRS as data: its items, their equations and units, and the four
// traceability matrices as the SRS declares them.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace gp::verification {

/// A dependency "from uses to" (an item on an assumption, or a model on another model).
using Edge = std::pair<std::string, std::string>;

/// A theoretical model, general definition, data definition or instance model.
struct Model {
  std::string id;        ///< e.g. "DD:ctrOfMass"
  std::string kind;      ///< "TM", "GD", "DD" or "IM"
  std::string label;     ///< e.g. "Center of Mass"
  std::string equation;  ///< LaTeX, as the SRS writes it
};

/// An item that is not a model: goal, assumption, requirement, likely or unlikely change.
struct Item {
  std::string id;
  std::string text;
};

struct Catalog {
  std::vector<Item> goals;
  std::vector<Item> assumptions;
  std::vector<Model> models;  ///< TMs, GDs, DDs, IMs in SRS order
  std::vector<Item> functional_requirements;
  std::vector<Item> nonfunctional_requirements;
  std::vector<Item> likely_changes;
  std::vector<Item> unlikely_changes;
  std::size_t input_constraints = 0;
  std::size_t output_constraints = 0;
  std::vector<Edge> assumptions_vs_assumptions;  ///< (assumption, assumption it depends on)
  std::vector<Edge> assumptions_vs_items;        ///< (item, assumption it depends on)
  std::vector<Edge> items_vs_items;              ///< (model, model it uses)
  std::vector<Edge> requirements_vs_items;       ///< (requirement or goal, model)
  nlohmann::json json;                           ///< the whole file, for the fields not above

  /// Every id in the catalogue, in SRS order.
  std::vector<std::string> all_ids() const;
  /// Whether `id` names an item of the catalogue.
  bool contains(const std::string& id) const;
};

/// Reads and checks the shape of a catalogue file; throws std::runtime_error naming the file.
Catalog load_catalog(const std::filesystem::path& file);

}  // namespace gp::verification
