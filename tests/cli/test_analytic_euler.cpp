// newtop analytic --json, Lagrange case: "euler_angles" carries the 3-1-3 angles of
// lagrange_euler_angles (checked against the integrated attitude in
// tests/integrable/test_lagrange_case.cpp) and the symmetry axis in the fixed frame, at the sample
// times: here the JSON against its own samples (γ from θ and ψ, the axis from θ and φ).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace test_analytic_euler {
namespace {

/// The angles and the samples come from the same closed form evaluated at the same t: they agree
/// to the round-off of a few trigonometric functions of O(1) arguments (measured 2e-16).
constexpr double kRoundOff = 1e-13;

TEST(AnalyticEuler, LagrangeJsonHasTheEulerAnglesAndTheAxisAtTheSampleTimes) {
  const auto r = newtop::test::run_newtop(
      "analytic " + newtop::test::example_path("analytic_lagrange.toml") + " --samples 25 --json",
      newtop::test::Stderr::separate);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& samples = j.at("samples");
  const auto& euler = j.at("euler_angles");
  ASSERT_EQ(euler.size(), samples.size());
  ASSERT_GE(euler.size(), 25u);                      // --samples 25: the intervals; t = 0 as well
  EXPECT_EQ(euler[0].at("phi").get<double>(), 0.0);  // x of the fixed frame: the node at t = 0
  for (std::size_t k = 0; k < euler.size(); ++k) {
    const auto& e = euler[k];
    ASSERT_EQ(e.at("t").get<double>(), samples[k].at("t").get<double>());
    const double phi = e.at("phi"), theta = e.at("theta"), psi = e.at("psi");
    const auto& g = samples[k].at("analytic").at("gamma");
    EXPECT_NEAR(std::sin(theta) * std::sin(psi), g[0].get<double>(), kRoundOff) << k;
    EXPECT_NEAR(std::sin(theta) * std::cos(psi), g[1].get<double>(), kRoundOff) << k;
    EXPECT_NEAR(std::cos(theta), g[2].get<double>(), kRoundOff) << k;
    // R_z(φ) R_x(θ) e3 = (sin θ sin φ, −sin θ cos φ, cos θ)
    const auto& a = e.at("axis");
    EXPECT_NEAR(a[0].get<double>(), std::sin(theta) * std::sin(phi), kRoundOff) << k;
    EXPECT_NEAR(a[1].get<double>(), -std::sin(theta) * std::cos(phi), kRoundOff) << k;
    EXPECT_NEAR(a[2].get<double>(), std::cos(theta), kRoundOff) << k;
  }
  // The precession advances: the axis goes round e (not a fixed point of the picture).
  EXPECT_GT(std::abs(euler.back().at("phi").get<double>()), 0.1);
}

// The curve of --dense is the closed form between the samples: at its ends the samples' own
// states (same function, same t: the same bits), and in between it agrees with an independent
// rkf78 run at tol 1e-13 to the examples' bound for the integrable cases (examples/CMakeLists.txt:
// the reference's global error over 20 time units is 1e-13 to 6e-12; 1e-10).
constexpr double kReferenceAgreement = 1e-10;

TEST(AnalyticEuler, CurveIsTheClosedFormBetweenTheSamples) {
  using newtop::test::run_newtop;
  const std::string ex = newtop::test::example_path("analytic_lagrange.toml");
  const auto r = run_newtop("analytic " + ex + " --samples 4 --dense 41 --json",
                            newtop::test::Stderr::separate);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& curve = j.at("dense");
  const auto& samples = j.at("samples");
  ASSERT_EQ(curve.at("t").size(), 41u);
  ASSERT_EQ(curve.at("euler_angles").size(), 41u);
  EXPECT_EQ(curve.at("gamma")[0], samples[0].at("analytic").at("gamma"));
  EXPECT_EQ(curve.at("gamma")[40], samples.back().at("analytic").at("gamma"));
  EXPECT_EQ(curve.at("t")[40].get<double>(), samples.back().at("t").get<double>());
  for (const int k : {7, 23, 33}) {  // between the samples
    const double t = curve.at("t")[k].get<double>();
    char times[64];
    std::snprintf(times, sizeof(times), "%.17g", t);
    const auto ref = run_newtop("analytic " + ex + " --times " + times + " --json",
                                newtop::test::Stderr::separate);
    ASSERT_EQ(ref.code, 0) << ref.err;
    const auto parsed = nlohmann::json::parse(ref.out);
    const auto& numeric = parsed.at("samples")[0].at("numeric");
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(curve.at("gamma")[k][i].get<double>(), numeric.at("gamma")[i].get<double>(),
                  kReferenceAgreement);
      EXPECT_NEAR(curve.at("omega")[k][i].get<double>(), numeric.at("omega")[i].get<double>(),
                  kReferenceAgreement);
    }
  }
}

TEST(AnalyticEuler, CurveNeedsJsonAndASolvedCase) {
  using newtop::test::run_newtop;
  const auto no_json =
      run_newtop("analytic " + newtop::test::example_path("analytic_lagrange.toml") + " --dense 10",
                 newtop::test::Stderr::separate);
  EXPECT_EQ(no_json.code, 2);
  const auto small = run_newtop(
      "analytic " + newtop::test::example_path("analytic_lagrange.toml") + " --dense 1 --json",
      newtop::test::Stderr::separate);
  EXPECT_EQ(small.code, 2);
  EXPECT_NE(small.err.find("--dense"), std::string::npos) << small.err;
}

}  // namespace
}  // namespace test_analytic_euler
