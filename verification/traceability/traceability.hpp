#pragma once
// Traceability between the SRS and the code: which function implements each SRS model, which tests
// verify it, and how the edges the code uses differ from the edges the SRS declares.

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "gamephysics/models/registry.hpp"
#include "verification/dimensions/dimensional_audit.hpp"
#include "verification/srs/catalog.hpp"
#include "verification/srs/errata.hpp"
#include "verification/srs/erratum_citations.hpp"
#include "verification/traceability/test_index.hpp"
#include "verification/traceability/test_results.hpp"

namespace gp::verification {

/// Everything the traceability check reads.
struct TraceInputs {
  Catalog catalog;
  std::vector<models::Registration> registrations;
  std::map<std::string, std::vector<std::string>> calls;  ///< model id -> model ids its file calls
  std::vector<TestCase> tests;
  std::map<std::string, std::set<std::string>> test_calls;  ///< test name -> models its body calls
  std::optional<TestResults> results;  ///< the Catch2 run's results, when the caller has them
  std::vector<Erratum> errata;
  std::vector<Citation> citations;  ///< erratum ids cited in code, tests and docs
  std::vector<DimensionalCheck> dimensions;
};

/// Reads srs/catalog.json, srs/errata.md, tests/ and the model registrations under `root`.
TraceInputs gather_trace_inputs(const std::filesystem::path& root);

enum class EdgeStatus { matched, srs_only, code_only };

/// A model-to-model edge and where it is declared.
struct EdgeRow {
  Edge edge;
  EdgeStatus status;
  std::string erratum;  ///< id of the erratum that explains a difference; empty if none
};

struct TraceResult {
  std::vector<EdgeRow> edges;         ///< union of SRS and code edges, sorted
  std::vector<std::string> problems;  ///< every failed check, one line each; empty when all pass
};

/// Runs every traceability check: each model has one function and a test that calls it (and,
/// with results, passes), each test tagged with a model calls its function, registrations match
/// the calls in the code, each edge difference and each failed dimensional check has an erratum,
/// each erratum names existing items and tests, each cited erratum id exists.
TraceResult analyse(const TraceInputs& inputs);

/// Tests tagged with `id`, in index order.
std::vector<const TestCase*> tagged_tests(const TraceInputs& inputs, const std::string& id);

/// Tests tagged with `id` whose body calls its function (directly or through the models that
/// call it): the tests that count as testing it.
std::vector<const TestCase*> tests_of(const TraceInputs& inputs, const std::string& id);

/// Tests tagged "via:" + `id`: they exercise the model only through the engine or the oracle, and
/// do not count as testing its function.
std::vector<const TestCase*> tests_through_engine(const TraceInputs& inputs, const std::string& id);

/// Of tests_of, those that passed in inputs.results; all of them when there are no results.
std::vector<const TestCase*> passing_tests_of(const TraceInputs& inputs, const std::string& id);

}  // namespace gp::verification
