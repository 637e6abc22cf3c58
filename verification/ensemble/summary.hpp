#pragma once
// The summary of an ensemble's samples.csv: per numeric column, over the samples that ran, the
// count, mean, standard deviation, extremes and quantiles; and how many samples failed.

#include <istream>
#include <nlohmann/json.hpp>

namespace gp::verification {

/// Quantiles of the summary: the median, the quartiles and the 5% and 95% points.
inline constexpr double kSummaryQuantiles[] = {0.05, 0.25, 0.5, 0.75, 0.95};

/// Reads samples.csv (SampleTable's columns) and returns {"samples", "failed", "errors" (the
/// first few messages), "columns": {name: {count, mean, std, min, q05, ..., max}}}. The standard
/// deviation is the sample one (n − 1); quantiles interpolate linearly between order statistics.
nlohmann::ordered_json summarize_samples(std::istream& samples_csv);

}  // namespace gp::verification
