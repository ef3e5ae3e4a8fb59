// Every subcommand on an exact-field scenario reports the exact field's values (against a
// 100-digit reference of the box's field) and says which field it used; the quadratic-only
// analyses refuse it with one line naming the field.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "bodies.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_model_cli {
namespace {

using test::CliResult;
using test::run_newtop;

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// A box off its centre in the exact field, near enough (R = 6, r ≈ 2.3) for the octupole to
// count, given in a frame that is not its principal axes' (the body rotates into them).
const Vec3 kLo(-0.4, -0.8, -0.6),
    kHi(0.6, 1.2, 2.4);  // dimensions 1 × 2 × 3, centre (0.1, 0.2, 0.9)
constexpr double kDensity = 2.0, kMu = 3.0, kR = 6.0;
const Vec3 kOmega(0.1, 0.0, 0.3), kGammaUser = Vec3(0.0, 0.6, 0.8);
const std::string kScenario = R"(
[mass_model]
kind = "box"
dimensions = [1.0, 2.0, 3.0]
density = 2.0
center = [0.1, 0.2, 0.9]

[field]
kind = "exact"
mu = 3.0
R = 6.0

[initial]
omega = [0.1, 0.0, 0.3]
gamma = [0.0, 0.6, 0.8]

[integrate]
t_end = 1.0
step = 0.01
)";

/// V at a user-frame γ from the 100-digit reference.
double reference_V(const Vec3& gamma_user) {
  return test::lower_all(test::box<test::Real100>(kLo, kHi, kDensity, kMu, kR, gamma_user))
      .potential;
}

/// ½ ω·Jω + V at the initial state (user frame: J about O of the homogeneous box).
double reference_energy() {
  const MassProperties mp = mass_properties(make_box(kHi - kLo, kDensity, 0.5 * (kLo + kHi)));
  return 0.5 * kOmega.dot(mp.inertia_tensor * kOmega) + reference_V(kGammaUser);
}

// The closed form near the box (R/r ≈ 2.6) loses ≲ 100 ε (R/r)² ≈ 1.5e-13 of V; JSON numbers
// round-trip exactly. 1e-12 relative.
constexpr double kTol = 1e-12;

nlohmann::json json_of(const std::string& args) {
  const CliResult r = run_newtop(args, test::Stderr::separate);
  EXPECT_EQ(r.code, 0) << args << "\n" << r.out << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(ModelCli, IntegralsAndSimulateReportTheExactFieldsEnergy) {
  const std::string f = write("model_box.toml", kScenario);
  const double E = reference_energy();
  const auto ji = json_of("integrals " + f + " --json");
  EXPECT_EQ(ji["field"]["kind"], "exact");
  EXPECT_EQ(ji["field"]["mu"].get<double>(), kMu);
  EXPECT_EQ(ji["field"]["R"].get<double>(), kR);
  EXPECT_NEAR(ji["integrals"]["energy"].get<double>(), E, kTol * std::abs(E));
  EXPECT_FALSE(ji["integrals"].contains("brun"));
  EXPECT_FALSE(ji["model"].contains("lambda"));  // no quadratic stand-in under the model's name
  const std::string csv = ::testing::TempDir() + "model_box.csv";
  const auto js = json_of("simulate " + f + " --json --out " + csv);
  EXPECT_EQ(js["field"]["kind"], "exact");
  EXPECT_EQ(js["integrals"]["initial"]["energy"], ji["integrals"]["energy"]);
  // A splitting method conserves the exact field's energy to O(h⁴) here, not the quadratic one's.
  EXPECT_LE(js["integrals"]["max_abs_drift"]["energy"].get<double>(), 1e-6 * std::abs(E));
  std::ifstream in(csv);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "t,p,q,r,gamma1,gamma2,gamma3,energy,area,geometric");
  std::stringstream row(first);
  std::string cell;
  for (int i = 0; i < 8; ++i) std::getline(row, cell, ',');
  EXPECT_NEAR(std::stod(cell), E, kTol * std::abs(E)) << first;
  const CliResult human = run_newtop("integrals " + f);
  EXPECT_NE(human.out.find("field     exact (mu = 3, R = 6"), std::string::npos) << human.out;
}

TEST(ModelCli, EquilibriaAreTheExactFieldsWithTheCountRule) {
  const std::string f = write("model_box_eq.toml", kScenario);
  const auto j = json_of("equilibria " + f + " --json");
  EXPECT_EQ(j["field"]["kind"], "exact");
  EXPECT_TRUE(j["count_rule"]["holds"].get<bool>());
  EXPECT_EQ(j["count_rule"]["minima_minus_saddles_plus_maxima"].get<int>(), 2);
  const auto& P = j["model"]["principal_axes"];  // columns: principal axes in the user frame
  // The offset box: one minimum and one maximum (the dipole term dominates).
  EXPECT_EQ(j["minima"].get<int>(), 1);
  EXPECT_EQ(j["maxima"].get<int>(), 1);
  ASSERT_EQ(j["equilibria"].size(), 2u);
  for (const auto& e : j["equilibria"]) {
    Vec3 g_user = Vec3::Zero();
    for (int c = 0; c < 3; ++c) {
      for (int i = 0; i < 3; ++i) g_user[i] += P[c][i].get<double>() * e["gamma"][c].get<double>();
    }
    const double V = reference_V(g_user);
    EXPECT_NEAR(e["potential"].get<double>(), V, kTol * std::abs(V));
    EXPECT_FALSE(e.contains("staude_residual"));
  }
}

TEST(ModelCli, StabilityOfAnExactFieldEquilibriumUsesTheField) {
  const std::string f = write("model_box_st.toml", kScenario);
  const auto eq = json_of("equilibria " + f + " --json");
  for (std::size_t k = 0; k < eq["equilibria"].size(); ++k) {
    const std::string type = eq["equilibria"][k]["type"];
    const auto j =
        json_of("stability " + f + " --equilibrium " + std::to_string(k + 1) + " --json");
    EXPECT_EQ(j["field"]["kind"], "exact");
    // At rest, a minimum of the exact V is stable (energy–Casimir), a saddle or maximum not.
    EXPECT_EQ(j["linearly_stable"].get<bool>(), type == "minimum") << k << " " << type;
  }
}

TEST(ModelCli, QuadraticOnlyAnalysesRefuseTheExactFieldInOneLine) {
  const std::string f = write("model_box_refuse.toml", kScenario);
  for (const std::string cmd : {"analytic", "find-integrals", "stability --axis z"}) {
    const CliResult r = run_newtop(cmd + " " + f);
    EXPECT_EQ(r.code, 2) << cmd << ": " << r.out;
    EXPECT_NE(r.out.find("[field] kind: "), std::string::npos) << cmd << ": " << r.out;
    EXPECT_NE(r.out.find("found the exact (mu = 3, R = 6"), std::string::npos)
        << cmd << ": " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << cmd << ": " << r.out;
  }
}

}  // namespace
}  // namespace test_model_cli
}  // namespace newtop
