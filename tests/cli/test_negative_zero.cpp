// docs/cli.md: "Zero is written 0, never -0", in the JSON and in the human summary. The heavy top
// of examples/heavy_top.toml has λ = 0 and C < A, so the Lagrange quartic's a1 = λ(C − A)/A is the
// floating-point −0 (0 times a negative number), which nlohmann-json writes as -0.0.

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "support/cli.hpp"

namespace test_negative_zero {
namespace {

using newtop::test::example_path;
using newtop::test::run_newtop;

/// A number token that is a zero with a minus sign: -0, -0.0, -0.000 (not -0.5, not 1e-05).
const std::regex kNegativeZero(R"((^|[^0-9.eE])-0(\.0*)?([^0-9.eE]|$))");

TEST(NegativeZero, AnalyticWritesTheLagrangeQuarticWithoutMinusZero) {
  const auto json =
      run_newtop("analytic " + example_path("heavy_top.toml") + " --samples 3 --json");
  ASSERT_EQ(json.code, 0) << json.out;
  EXPECT_NE(json.out.find("\"a1\": 0"), std::string::npos) << json.out;
  EXPECT_FALSE(std::regex_search(json.out, kNegativeZero)) << json.out;

  const auto human = run_newtop("analytic " + example_path("heavy_top.toml") + " --samples 3");
  ASSERT_EQ(human.code, 0) << human.out;
  EXPECT_NE(human.out.find("a1 = 0"), std::string::npos) << human.out;
  EXPECT_FALSE(std::regex_search(human.out, kNegativeZero)) << human.out;
}

}  // namespace
}  // namespace test_negative_zero
