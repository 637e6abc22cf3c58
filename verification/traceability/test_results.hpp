#pragma once
// The results of a run of the Catch2 tests, read from its JUnit XML report
// (build/bin/gamephysics_tests -r junit -o FILE), for the audit page.

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace gp::verification {

/// Reported name -> whether it passed. Catch2 reports a test case as its name and each of its
/// sections as "name/section".
using TestResults = std::map<std::string, bool>;

/// Reads the <testcase> elements of a JUnit XML file; a case with a <failure> or <error> child
/// failed. Throws std::runtime_error when the file cannot be read or holds no test case.
TestResults load_test_results(const std::filesystem::path& file);

/// Whether test case `name` passed (it and all its sections), or nothing when it is not in
/// `results`. Test names may themselves contain '/'.
std::optional<bool> result_of(const TestResults& results, const std::string& name);

}  // namespace gp::verification
