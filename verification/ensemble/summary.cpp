#include "verification/ensemble/summary.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gp::verification {

namespace {

// The cells of a CSV line; quoted cells may hold commas and doubled quotes.
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

// The q-quantile of sorted `v` (linear between order statistics, R's type 7).
double quantile(const std::vector<double>& v, double q) {
  const double position = q * static_cast<double>(v.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, v.size() - 1);
  return v[below] + (position - static_cast<double>(below)) * (v[above] - v[below]);
}

nlohmann::ordered_json statistics(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double sum = 0.0;
  for (double x : v) sum += x;
  const double mean = sum / static_cast<double>(v.size());
  double squares = 0.0;
  for (double x : v) squares += (x - mean) * (x - mean);
  nlohmann::ordered_json s;
  s["count"] = v.size();
  s["mean"] = mean;
  s["std"] = v.size() > 1 ? std::sqrt(squares / static_cast<double>(v.size() - 1)) : 0.0;
  s["min"] = v.front();
  for (double q : kSummaryQuantiles) {
    char name[8];
    std::snprintf(name, sizeof name, "q%02d", static_cast<int>(std::lround(q * 100)));
    s[name] = quantile(v, q);
  }
  s["max"] = v.back();
  return s;
}

}  // namespace

nlohmann::ordered_json summarize_samples(std::istream& samples_csv) {
  std::string line;
  std::getline(samples_csv, line);
  const std::vector<std::string> header = cells_of(line);
  const std::size_t error_column = header.size() - 1;
  std::vector<std::vector<double>> columns(header.size());
  std::size_t samples = 0, failed = 0;
  nlohmann::ordered_json errors = nlohmann::ordered_json::array();
  while (std::getline(samples_csv, line)) {
    const std::vector<std::string> cells = cells_of(line);
    ++samples;
    if (!cells[error_column].empty()) {
      ++failed;
      if (errors.size() < 5) errors.push_back("sample " + cells[0] + ": " + cells[error_column]);
      continue;
    }
    for (std::size_t c = 1; c < error_column; ++c) {
      double value = 0.0;
      const std::string& cell = cells[c];
      const auto [end, fault] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
      if (!cell.empty() && fault == std::errc() && end == cell.data() + cell.size()) {
        columns[c].push_back(value);
      }
    }
  }
  nlohmann::ordered_json summary;
  summary["samples"] = samples;
  summary["failed"] = failed;
  summary["errors"] = errors;
  nlohmann::ordered_json stats = nlohmann::ordered_json::object();
  for (std::size_t c = 1; c < error_column; ++c) {
    if (!columns[c].empty()) stats[header[c]] = statistics(std::move(columns[c]));
  }
  summary["columns"] = stats;
  return summary;
}

}  // namespace gp::verification
