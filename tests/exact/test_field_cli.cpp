// The `newtop field` command and scenario files with [mass_model] (CLI: exit codes and JSON).

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "newtop/exact/exact_field.hpp"
#include "newtop/io/scenario.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace {

using test::CliResult;
using test::run_newtop;

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const std::string kBox = R"(
[mass_model]
kind = "box"
dimensions = [1.0, 2.0, 3.0]
density = 2.0
center = [0.1, 0.2, 0.9]

[field]
kind = "exact"
mu = 3.0
R = 12.0

[initial]
omega = [0.1, 0.0, 0.3]
gamma = [0.0, 0.6, 0.8]

[integrate]
t_end = 1.0
step = 0.01
)";

TEST(FieldCli, JsonHasExactApproxAndDifference) {
  const std::string f = write("box.toml", kBox);
  const CliResult r = run_newtop("field " + f + " --gamma 0,0.6,0.8 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["mass_properties"]["mass"].get<double>(), 12.0, 1e-12);
  for (const char* k : {"potential", "grad_gamma", "dV_dR", "moment", "force"}) {
    EXPECT_TRUE(j["exact"].contains(k) && j["approx"].contains(k) && j["difference"].contains(k))
        << k;
  }
  // Difference = exact − approx, and the approximation is close (R = 12 ≫ size): relative O((r/R)).
  const double ve = j["exact"]["potential"], va = j["approx"]["potential"],
               d = j["difference"]["potential"];
  EXPECT_DOUBLE_EQ(d, ve - va);
  EXPECT_LT(std::abs(d), 1e-2 * std::abs(ve));
}

TEST(FieldCli, ScanGivesMinusFourSlopeForTheMoment) {
  const std::string f = write("box2.toml", kBox);
  const CliResult r = run_newtop("field " + f + " --gamma 0,0.6,0.8 --scan-R 40:320:4 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  // Offset box: nonzero octupole; the next order bends the slope by ~ r/R ≤ 0.1 at R = 40 only.
  EXPECT_NEAR(j["scan"]["slope_moment"].get<double>(), -4.0, 0.05);
}

TEST(FieldCli, BadInputIsOneLineWithExitCode2) {
  const std::string f = write("box3.toml", kBox);
  const CliResult r = run_newtop("field " + f + " --gamma 0,0,0");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--gamma"), std::string::npos);
  std::string bad = kBox;
  bad.replace(bad.find("R = 12.0"), 8, "R = 1.0");
  const CliResult inside = run_newtop("field " + write("box4.toml", bad) + " --gamma 0,0.6,0.8");
  EXPECT_EQ(inside.code, 2);
  EXPECT_NE(inside.out.find("[field] R: expected a distance greater than"), std::string::npos)
      << inside.out;
}

TEST(ScenarioMassModel, BodyMustAgreeWithMassModel) {
  const std::string good = kBox + "\n[body]\ngyrostat = [0.0, 0.0, 0.5]\n";
  const io::Scenario s = io::parse_scenario(good, "good.toml");
  EXPECT_EQ(s.exact.kind, io::FieldKind::exact);
  EXPECT_NEAR(s.model.body.mass(), 12.0, 1e-12);
  const std::string bad = kBox + "\n[body]\ninertia = [1.0, 2.0, 2.5]\nmass = 12.0\n";
  try {
    io::parse_scenario(bad, "bad.toml");
    FAIL() << "accepted a [body] that disagrees with [mass_model]";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("disagree"), std::string::npos) << msg;
    EXPECT_NE(msg.find("inertia tensor"), std::string::npos) << msg;
    EXPECT_NE(msg.find("center_of_mass"), std::string::npos) << msg;
    EXPECT_EQ(msg.find(" mass: [body]"), std::string::npos) << msg;  // the mass agrees
  }
}

TEST(SimulateCli, ExactFieldRunReportsQuadraticComparison) {
  const std::string f = write("box5.toml", kBox);
  const CliResult r = run_newtop("simulate " + f + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["field"]["kind"], "exact");
  EXPECT_GT(j["quadratic_comparison"]["difference_gamma"].get<double>(), 0.0);
}

}  // namespace
}  // namespace newtop
