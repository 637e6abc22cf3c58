#include <catch2/catch.hpp>

#include "scene/input_error.hpp"

namespace {
namespace test_input_error {

TEST_CASE("An input error names the field, the rule and the value",
          "[FR:Verify-Physical_Constraints]") {
  const gp::InputError error("bodies[3].mass", "must be > 0 (SRS data constraint)", "-1");
  CHECK(std::string(error.what()) == "bodies[3].mass: must be > 0 (SRS data constraint), got -1");
  CHECK(error.field() == "bodies[3].mass");
  CHECK(error.rule() == "must be > 0 (SRS data constraint)");
  CHECK(error.value() == "-1");
}

}  // namespace test_input_error
}  // namespace
