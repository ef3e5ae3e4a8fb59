// The `newtop field` command and scenario files with [mass_model] (CLI: exit codes and JSON).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "newtop/exact/exact_field.hpp"
#include "newtop/io/scenario.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_field_cli {
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

// The six-point spacecraft of a gravity-gradient unit test in low Earth orbit (R/r = 7e6):
// I = diag(500, 800, 350), r0 = 0.
const std::string kLeo = R"(
[mass_model]
kind = "points"
points = [[162.5, 1, 0, 0], [162.5, -1, 0, 0], [12.5, 0, 1, 0], [12.5, 0, -1, 0],
          [237.5, 0, 0, 1], [237.5, 0, 0, -1]]

[field]
kind = "exact"
mu = 3.986004360e14
R = 6999942.573514503

[initial]
omega = [0.001, -0.0004, 0.0011]
gamma = [-0.95855, -0.13584, -0.25046]
normalize = true

[integrate]
t_end = 100.0
step = 0.1
method = "splitting4"
)";

Vec3 vec(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2]}; }

TEST(FieldCli, LowEarthOrbitSpacecraftMomentToTheLastDigit) {
  // The moment far from a small body: γ × ∂V/∂γ would cancel (R/r)² ≈ 5e13 of its digits (1e-2
  // relative error). The published truth to 5 digits, and the quadratic model's moment (the
  // approximation is exact to the hexadecapole, (r/R)² ≈ 2e-14 relative: r0 = 0 and every odd
  // moment vanishes) to round-off.
  const std::string f = write("leo.toml", kLeo);
  const CliResult r = run_newtop("field " + f + " --gamma -0.95855,-0.13584,-0.25046 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const Vec3 L = vec(j["exact"]["moment"]), Lq = vec(j["approx"]["moment"]);
  const Vec3 truth(-5.3376e-5, 1.2555e-4, 1.3619e-4);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(L[i], truth[i], 0.5e-4 * std::abs(truth[i])) << i;  // half a unit of 5 digits
  }
  // 32 ε of round-off (test_moment_accuracy.cpp) plus the hexadecapole: against the quadrupole's
  // moment (r/R)² times max|P4'|/max|P2'| = 10/3 times Σ m|ρ|²/min|I_i − I_j| = 825/150 for the
  // anisotropy the quadrupole's moment rests on: 18 (r/R)² ≈ 3.7e-13 (measured 1.7e-13).
  const double tol = 32 * 2.2e-16 + 18 / (7e6 * 7e6);
  EXPECT_LE((L - Lq).norm(), tol * Lq.norm()) << L.transpose() << " vs " << Lq.transpose();
  // The force's tangential part γ × L / R comes from the same moment.
  const Vec3 g = vec(j["gamma"]), F = vec(j["exact"]["force"]), Fq = vec(j["approx"]["force"]);
  const Vec3 Ft = F - F.dot(g) * g, Fqt = Fq - Fq.dot(g) * g;
  EXPECT_LE((Ft - Fqt).norm(), tol * Fqt.norm() + 4 * 2.2e-16 * F.norm());
}

TEST(SimulateCli, MultipoleOrderThreeIsTheQuadraticModelToRoundOff) {
  // docs/exact_field.md: order 3 is the quadratic model. Same method and steps: the runs differ
  // only by the moments' round-off, ≤ 32 ε relative per kick, and the |γ| − 1 ≈ ε of the free
  // vector's extension; over N = 1000 steps of a nearly linear 100 s (ω T ≈ 0.1) a random walk of
  // 32 ε √N ≈ 2e-13 bounds both the γ and the relative ω difference.
  std::string text = kLeo;
  text.replace(text.find("kind = \"exact\""), 14, "kind = \"multipole\"\norder = 3");
  const CliResult r = run_newtop("simulate " + write("leo_mp.toml", text) + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["field"]["order"], 3);
  const double tol = 32 * 2.2e-16 * std::sqrt(1000.0);
  EXPECT_LE(j["quadratic_comparison"]["difference_gamma"].get<double>(), tol);
  const double w = vec(j["quadratic_comparison"]["omega"]).norm();
  EXPECT_LE(j["quadratic_comparison"]["difference_omega"].get<double>(), tol * w);
}

TEST(FieldCli, ExactEllipsoidFarAwayIsFinite) {
  // An exact ellipsoid field at R = 7e8 semi-axes once ended in exit 1 from the root finder of
  // the confocal parameter; far away it is the series, and the closed form itself is well posed.
  const std::string text = R"(
[mass_model]
kind = "ellipsoid"
semi_axes = [1.0, 2.0, 3.0]
density = 1.0

[field]
kind = "exact"
mu = 1.0
R = 7e8

[initial]
omega = [0.001, 0.0, 0.0011]
gamma = [0, 0.6, 0.8]

[integrate]
t_end = 1.0
step = 0.1
)";
  const std::string f = write("ellipsoid_far.toml", text);
  const CliResult s = run_newtop("simulate " + f + " --json");
  EXPECT_EQ(s.code, 0) << s.out;
  const CliResult r = run_newtop("field " + f + " --gamma 0,0.6,0.8 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const Vec3 L = vec(j["exact"]["moment"]), Lq = vec(j["approx"]["moment"]);
  // Centred ellipsoid: next term (r/R)² ≈ 2e-17, below round-off (32 ε).
  EXPECT_LE((L - Lq).norm(), 32 * 2.2e-16 * Lq.norm()) << L.transpose() << " vs " << Lq.transpose();
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
  EXPECT_EQ(s.model.kind(), FieldKind::exact);
  EXPECT_NEAR(s.model.body().mass(), 12.0, 1e-12);
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
}  // namespace test_field_cli
}  // namespace newtop
