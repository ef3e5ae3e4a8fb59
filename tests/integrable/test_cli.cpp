// The analytic and find-integrals commands end to end: JSON shape, agreement reported for the
// example scenarios, the --potential file, and one-line errors with exit code 2.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace test_cli {
namespace {

using newtop::test::CliResult;
using newtop::test::run_newtop;

std::string example(const std::string& name) { return newtop::test::example_path(name); }

// The analytic solutions agree with rkf78 to 1e-10 (tests of the library); the command reports it.
constexpr double kAgreement = 1e-10;

TEST(AnalyticCli, ReportsCaseAndAgreementForEachExample) {
  const std::pair<const char*, const char*> cases[] = {{"analytic_free_body.toml", "euler_poinsot"},
                                                       {"analytic_lagrange.toml", "lagrange"},
                                                       {"analytic_pendulum.toml", "pendulum"}};
  for (const auto& [file, name] : cases) {
    const CliResult r = run_newtop("analytic " + example(file) + " --samples 8 --json");
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["case"], name);
    EXPECT_EQ(j["samples"].size(), 9u);
    EXPECT_LT(j["max_abs_error"].get<double>(), kAgreement) << file;
    EXPECT_TRUE(j.contains("turning_points") && j.contains("period") &&
                j.contains("nutation_period"));
  }
  const auto lag = nlohmann::json::parse(
      run_newtop("analytic " + example("analytic_lagrange.toml") + " --times 0,1.5,3 --json").out);
  for (const char* k : {"E", "a", "a1", "b", "c", "gamma3"}) EXPECT_TRUE(lag.contains(k)) << k;
  EXPECT_EQ(lag["gamma3"].size(), 3u);
  const auto pen = nlohmann::json::parse(
      run_newtop("analytic " + example("analytic_pendulum.toml") + " --json").out);
  EXPECT_EQ(pen["kind"], "libration");
}

TEST(AnalyticCli, BadTimesIsOneLineAndExitCode2) {
  const CliResult r = run_newtop("analytic " + example("analytic_pendulum.toml") + " --times 1,x");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--times"), std::string::npos);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1);
}

TEST(FindIntegralsCli, JsonAndPolynomialPotential) {
  const CliResult r = run_newtop("find-integrals " + example("analytic_lagrange.toml") + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["integrals"].size(), 5u);
  EXPECT_TRUE(j.contains("rank") && j.contains("singular_values"));
  // V = ½ λ γ·Iγ for the free body's moments (1, 2, 3), λ = 0.5: Brun's integral appears unnamed.
  const std::string pot = testing::TempDir() + "newtop_potential.toml";
  std::ofstream(pot) << "[potential]\nterms = [[0.25, 2, 0, 0], [0.5, 0, 2, 0], [0.75, 0, 0, 2]]\n";
  const auto b =
      nlohmann::json::parse(run_newtop("find-integrals " + example("analytic_free_body.toml") +
                                       " --potential " + pot + " --json")
                                .out);
  EXPECT_EQ(b["integrals"].size(), 4u);
  EXPECT_TRUE(b["integrals"][3]["name"].is_null());
  std::ofstream(pot) << "[potential]\nterms = [[0.25, 2, 0]]\n";
  const CliResult bad =
      run_newtop("find-integrals " + example("analytic_free_body.toml") + " --potential " + pot);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.out.find("terms[0]"), std::string::npos);
}

}  // namespace
}  // namespace test_cli
