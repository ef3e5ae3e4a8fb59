// `newtop analytic` on Brun's case: the example on the level f = 0 reports the curve, the ranges of
// u1 and u2, the frequencies and samples that agree with rkf78; a start with f != 0 is solved by
// the inversion of the Abel-Prym map, with samples that agree with rkf78, the spectral curve of
// its level, the Prym divisor and the torus lattice.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "support/cli.hpp"

namespace test_brun_cli {
namespace {

using newtop::test::CliResult;
using newtop::test::run_newtop;

// The library's inversion matches rkf78 to 1e-9 (test_brun_case); the command reports it.
constexpr double kAgreement = 1e-9;

TEST(BrunCli, ReportsCurveRangesFrequenciesAndAgreement) {
  const CliResult r = run_newtop("analytic " + newtop::test::example_path("analytic_brun.toml") +
                                 " --samples 8 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["case"], "brun");
  EXPECT_EQ(j["samples"].size(), 9u);
  EXPECT_LT(j["max_abs_error"].get<double>(), kAgreement);
  EXPECT_EQ(j["curve"]["coefficients"].size(), 6u);
  EXPECT_EQ(j["curve"]["branch_points"].size(), 5u);
  EXPECT_EQ(j["u_ranges"].size(), 2u);
  EXPECT_EQ(j["frequencies"].size(), 2u);
  EXPECT_EQ(j["u"].size(), 9u);
  for (const auto& s : j["u"]) {
    for (int i = 0; i < 2; ++i) {
      const auto& range = j["u_ranges"][i];
      const double u = s[i == 0 ? "u1" : "u2"].get<double>();
      EXPECT_GE(u, range[0].get<double>());
      EXPECT_LE(u, range[1].get<double>());
    }
  }
  EXPECT_TRUE(j.contains("resonant") && j.contains("period_matrix") && j.contains("sign_flips"));
}

// A permanent rotation about an axis along γ (examples/stability_beletsky.toml: Brun's field, spin
// about z with γ = z) lies on a degenerate torus: its spectral curve is singular (two branch points
// merge), so there is nothing to invert; refused in one line (it once integrated the periods
// around the merged points without end).
TEST(BrunCli, DegenerateTorusIsRefusedInOneLine) {
  const CliResult r = run_newtop(
      "analytic " + newtop::test::example_path("stability_beletsky.toml") + " --samples 2",
      newtop::test::Stderr::separate);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("spectral curve is singular"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(BrunCli, NonzeroAreaIsSolvedByTheAbelPrymInversion) {
  const CliResult r =
      run_newtop("analytic " + newtop::test::example_path("brun.toml") + " --samples 6 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["case"], "brun");
  EXPECT_NE(j["reason"].get<std::string>().find("f != 0"), std::string::npos);
  // The analytic states at the 7 samples over [integrate] t_end = 100 against rkf78 (the
  // library's agreement, tests/integrable/test_brun_prym_inversion.cpp), with the time per sample.
  ASSERT_EQ(j["samples"].size(), 7u);
  for (const auto& s : j["samples"]) {
    EXPECT_TRUE(s["analytic"].contains("omega") && s["numeric"].contains("gamma"));
  }
  EXPECT_LT(j["max_abs_error"].get<double>(), kAgreement);
  EXPECT_GT(j["seconds_per_sample"].get<double>(), 0.0);
  // The spectral curve of the level: D(u) = N² − 4λf² P vanishes at the reported roots.
  const auto& sc = j["spectral_curve"];
  ASSERT_EQ(sc["discriminant"].size(), 5u);
  ASSERT_EQ(sc["discriminant_roots"].size(), 4u);
  EXPECT_NE(sc["f"].get<double>(), 0.0);
  for (const auto& root : sc["discriminant_roots"]) {
    std::complex<double> u(root[0].get<double>(), root[1].get<double>()), d(0.0), size(0.0);
    for (int i = 4; i >= 0; --i) {
      d = d * u + sc["discriminant"][i].get<double>();
      size = size * std::abs(u) + std::abs(sc["discriminant"][i].get<double>());
    }
    // Companion-matrix roots polished by Newton: D(root) at rounding of the largest term.
    EXPECT_LT(std::abs(d), 1e-12 * std::abs(size));
  }
  // The Prym divisor of the start (brun_prym.hpp): three points, the state back from them, and the
  // rates of the Abel-Prym sums at the start on the law (-2i/kappa, 0).
  const auto& p = j["prym"];
  ASSERT_EQ(p["divisor"].size(), 3u);
  EXPECT_LT(p["round_trip_error"].get<double>(), 1e-11);
  const double kappa = 1.0 * 1.5 * 2.2;
  EXPECT_NEAR(p["velocity"][0][1].get<double>(), -2 / kappa, 1e-15);
  EXPECT_NEAR(p["rate_at_start"][0][1].get<double>(), -2 / kappa, 1e-12);
  EXPECT_EQ(p["table_nodes"].get<int>(), 81);
  // The torus frequencies (brun_prym_periods.hpp, checked in test_brun_prym_periods.cpp) at the
  // top level as on f = 0, with the torus periods they come from.
  ASSERT_EQ(j["frequencies"].size(), 2u);
  EXPECT_EQ(j["frequencies"], p["torus"]["frequencies"]);
  const auto& T = p["torus"]["torus_periods"];
  const double det =
      T[0][0].get<double>() * T[1][1].get<double>() - T[1][0].get<double>() * T[0][1].get<double>();
  // ω = 2π T⁻¹ (1, 0).
  EXPECT_NEAR(j["frequencies"][0].get<double>(), 2 * std::numbers::pi * T[1][1].get<double>() / det,
              1e-12);
  EXPECT_NEAR(j["frequencies"][1].get<double>(),
              -2 * std::numbers::pi * T[0][1].get<double>() / det, 1e-12);
}

}  // namespace
}  // namespace test_brun_cli
