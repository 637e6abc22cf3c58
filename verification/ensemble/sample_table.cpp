#include "verification/ensemble/sample_table.hpp"

#include <charconv>

namespace gp::verification {

namespace {

// A free-text cell: quoted, with its quotes doubled and its line breaks flattened.
std::string text_cell(const std::string& text) {
  std::string cell = "\"";
  for (char c : text) {
    if (c == '"')
      cell += "\"\"";
    else
      cell += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return cell + "\"";
}

}  // namespace

std::string number_text(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

SampleTable::SampleTable(const Scene& nominal, std::vector<PerturbedInput> inputs, bool with_oracle,
                         std::vector<double> times)
    : inputs_(std::move(inputs)), with_oracle_(with_oracle), times_(std::move(times)) {
  for (std::size_t b = 0; b < nominal.bodies.size(); ++b) {
    names_.push_back(nominal.bodies[b].name);
    if (nominal.bodies[b].type != BodyType::Static) moving_.push_back(b);
  }
}

std::string SampleTable::samples_header() const {
  std::string h = "sample";
  for (const PerturbedInput& input : inputs_) h += "," + input.name;
  for (std::size_t b : moving_) {
    for (const char* q : {".x", ".y", ".angle", ".vx", ".vy", ".omega"}) {
      h += ",final." + names_[b] + q;
    }
  }
  h += ",impacts";
  for (std::size_t k = 1; k <= kRecordedImpacts; ++k) h += ",impact" + std::to_string(k) + "_t";
  h += ",final.energy";
  if (with_oracle_) h += ",oracle,oracle_position_error,oracle_velocity_error";
  return h + ",error";
}

std::string SampleTable::energy_header() const {
  std::string h = "sample";
  for (double t : times_) h += "," + number_text(t);
  return h;
}

std::string SampleTable::samples_row(std::uint64_t index, std::span<const double> values,
                                     const SampleOutputs& outputs) const {
  std::string row = std::to_string(index);
  for (double v : values) row += "," + number_text(v);
  const bool ran = outputs.error.empty();
  for (std::size_t b : moving_) {
    if (!ran) {
      row += ",,,,,,";
      continue;
    }
    const BodyState& s = outputs.final_states[b];
    for (double v : {s.position.x(), s.position.y(), s.angle, s.velocity.x(), s.velocity.y(),
                     s.angular_velocity}) {
      row += "," + number_text(v);
    }
  }
  row += "," + (ran ? std::to_string(outputs.impact_count) : std::string());
  for (std::size_t k = 0; k < kRecordedImpacts; ++k) {
    row += "," + (ran && k < outputs.impact_times.size() ? number_text(outputs.impact_times[k])
                                                         : std::string());
  }
  row += "," + (ran ? number_text(outputs.energy.back()) : std::string());
  if (with_oracle_) {
    if (outputs.oracle && outputs.oracle->status == "ok") {
      row += ",ok," + number_text(outputs.oracle->position_error) + "," +
             number_text(outputs.oracle->velocity_error);
    } else {
      row += "," + text_cell(outputs.oracle ? outputs.oracle->status : "not run") + ",,";
    }
  }
  return row + "," + (ran ? std::string() : text_cell(outputs.error));
}

std::string SampleTable::energy_row(std::uint64_t index, const SampleOutputs& outputs) const {
  std::string row = std::to_string(index);
  for (std::size_t k = 0; k < times_.size(); ++k) {
    row += "," + (k < outputs.energy.size() ? number_text(outputs.energy[k]) : std::string());
  }
  return row;
}

}  // namespace gp::verification
