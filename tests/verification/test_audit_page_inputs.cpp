// What the audit page reads besides the audit: KaTeX's fonts turned into data: URIs (base64,
// against the test vectors of RFC 4648) and the results of a Catch2 JUnit report.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "verification/audit/katex_inline.hpp"
#include "verification/traceability/test_results.hpp"

namespace {
namespace test_audit_page_inputs {

TEST_CASE("base64 gives the test vectors of RFC 4648") {
  using gp::verification::base64;
  CHECK(base64("") == "");
  CHECK(base64("f") == "Zg==");
  CHECK(base64("fo") == "Zm8=");
  CHECK(base64("foo") == "Zm9v");
  CHECK(base64("foob") == "Zm9vYg==");
  CHECK(base64("fooba") == "Zm9vYmE=");
  CHECK(base64("foobar") == "Zm9vYmFy");
  CHECK(base64(std::string("\xff\x00\x80", 3)) == "/wCA");
}

TEST_CASE("A JUnit report gives each test case's result, its sections and escaped names included") {
  const auto file =
      std::filesystem::temp_directory_path() / ("gp_junit_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(file)
      << "<testsuites><testsuite>"
         "<testcase classname=\"t\" name=\"A&apos;s law &amp; m/s\" time=\"0\" status=\"run\"/>"
         "<testcase classname=\"t\" name=\"B\" status=\"run\"/>"
         "<testcase classname=\"t\" name=\"B/one section\" status=\"run\">"
         "<failure message=\"x\">FAILED</failure></testcase>"
         "<testcase classname=\"t\" name=\"Bee\" status=\"run\"></testcase>"
         "</testsuite></testsuites>";
  const auto results = gp::verification::load_test_results(file);
  std::filesystem::remove(file);
  using gp::verification::result_of;
  CHECK(result_of(results, "A's law & m/s") == std::optional<bool>(true));
  CHECK(result_of(results, "B") == std::optional<bool>(false));   // a failed section fails it
  CHECK(result_of(results, "Bee") == std::optional<bool>(true));  // not a section of B
  CHECK(result_of(results, "A's law") == std::nullopt);
  CHECK(result_of(results, "C") == std::nullopt);
}

TEST_CASE("A report without test cases, or no report, is an error") {
  const auto file = std::filesystem::temp_directory_path() /
                    ("gp_junit_empty_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(file) << "<testsuites/>";
  CHECK_THROWS_WITH(gp::verification::load_test_results(file), Catch::Contains("no test case in"));
  std::filesystem::remove(file);
  CHECK_THROWS_WITH(gp::verification::load_test_results(file), Catch::Contains("cannot read"));
}

}  // namespace test_audit_page_inputs
}  // namespace
