// The equilibria, rotations and stability commands: JSON keys, CSV files, bad input.

#include "support/cli.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/rotations.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop {
namespace test_cli_test {
namespace {

namespace fs = std::filesystem;

using test::CliResult;
using test::example_path;

/// Runs `newtop ARGS` with stderr merged into the output.
CliResult newtop(const std::string& args) { return test::run_newtop(args); }

std::string example(const std::string& name) { return example_path(name); }

fs::path temp_file(const std::string& name) {
  return newtop::test::scratch_path("newtop_stability", name);
}

std::vector<std::string> lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> v;
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

TEST(StabilityCli, EquilibriaJsonListsEveryEquilibrium) {
  const std::string file = example("equilibria_newtonian.toml");
  const CliResult r = newtop("equilibria " + file + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = io::Json::parse(r.out);
  const QuadraticModel model = io::load_scenario(file).model.quadratic();
  ASSERT_EQ(j["count"].get<std::size_t>(), j["equilibria"].size());
  EXPECT_EQ(j["count"].get<std::size_t>(), find_equilibria(model).equilibria.size());
  EXPECT_TRUE(j["count_rule"]["holds"].get<bool>());
  for (const auto& e : j["equilibria"]) {
    const auto g = e["gamma"].get<std::vector<double>>();
    const Vec3 gamma(g[0], g[1], g[2]);
    // Printed to 17 digits: γ × ∂V/∂γ is round-off of the size of ∂V/∂γ.
    EXPECT_LE(gamma.cross(grad_gamma(model, gamma)).norm(), 1e-14);
    EXPECT_DOUBLE_EQ(e["potential"].get<double>(), potential(model, gamma));
    EXPECT_TRUE(e["kappa"].is_number());
    const std::string type = e["type"].get<std::string>();
    EXPECT_TRUE(type == "minimum" || type == "saddle" || type == "maximum") << type;
  }
}

TEST(StabilityCli, RotationsWritesTheConeToCsv) {
  const std::string file = example("rotation_staude_cone.toml");
  const fs::path csv = temp_file("cone.csv");
  const CliResult r = newtop("rotations " + file + " --json --samples 20 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = io::Json::parse(r.out);
  const auto rows = lines(csv);
  fs::remove(csv);
  ASSERT_EQ(rows.front(), "gamma1,gamma2,gamma3,omega_squared,admissible");
  EXPECT_EQ(rows.size() - 1, j["cone_samples"].get<std::size_t>());
  const Body body = io::load_scenario(file).model.body();
  for (std::size_t i = 1; i < rows.size(); ++i) {
    Vec3 g;
    ASSERT_EQ(std::sscanf(rows[i].c_str(), "%lf,%lf,%lf", &g.x(), &g.y(), &g.z()), 3);
    EXPECT_LE(std::abs(staude_cone(body, g)), 1e-14) << rows[i];
  }
}

TEST(StabilityCli, StabilityJsonForBeletskySpin) {
  const CliResult r = newtop("stability " + example("stability_beletsky.toml") + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = io::Json::parse(r.out);
  for (const char* key : {"eigenvalues", "max_real_part", "linearly_stable", "lyapunov_stable",
                          "threshold_omega_formula", "threshold_omega_numeric"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["eigenvalues"].size(), 4u);
  EXPECT_TRUE(j["linearly_stable"].get<bool>());
  // Ω = 1.2 > √λ = 1 about the largest axis: the energy–Casimir function is definite
  // ((C − A)(Ω² − λ) > 0 and (C − B)(Ω² − λ) > 0, spin_test.cpp), so Lyapunov stable.
  EXPECT_EQ(j["lyapunov_stable"], true);
  EXPECT_EQ(j["axis_class"], "largest");
  EXPECT_NEAR(j["threshold_omega_numeric"].get<double>(),
              j["threshold_omega_formula"].get<double>(), 1e-9);
  // Below the threshold the same spin is unstable.
  const auto below = io::Json::parse(
      newtop("stability " + example("stability_beletsky.toml") + " --json --axis z --omega 0.5")
          .out);
  EXPECT_FALSE(below["linearly_stable"].get<bool>());
  EXPECT_EQ(below["lyapunov_stable"], false);
}

// The summary of a spin about an axis where Beletsky's formula does not apply says what the
// formula needs and what the axis is (not a list that reads as a description of the axis).
TEST(StabilityCli, FormulaNotApplicableSaysWhatTheAxisIs) {
  const CliResult y = newtop("stability " + example("stability_beletsky.toml") + " --axis y");
  ASSERT_EQ(y.code, 0) << y.out;
  EXPECT_NE(y.out.find("not applicable: the formula needs the largest-moment axis, r0 = 0 and "
                       "lambda > 0; y is the middle-moment axis"),
            std::string::npos)
      << y.out;
  const CliResult x = newtop("stability " + example("stability_beletsky.toml") + " --axis x");
  EXPECT_NE(x.out.find("; x is the least-moment axis"), std::string::npos) << x.out;
  // The JSON is unchanged: null where the formula does not apply.
  const auto j = io::Json::parse(
      newtop("stability " + example("stability_beletsky.toml") + " --axis y --json").out);
  EXPECT_TRUE(j["threshold_omega_formula"].is_null());
}

TEST(StabilityCli, ScansWriteCsvDiagrams) {
  const fs::path csv = temp_file("scan.csv");
  const std::string file = example("stability_beletsky.toml");
  CliResult r = newtop("stability " + file + " --json --scan-omega 0:3:31 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(io::Json::parse(r.out)["scan"].size(), 31u);
  EXPECT_EQ(lines(csv).size(), 32u);
  r = newtop("stability " + file + " --scan omega=0:3:5,C=1:3:4 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto rows = lines(csv);
  fs::remove(csv);
  ASSERT_EQ(rows.size(), 21u);
  EXPECT_EQ(rows.front(), "omega,C,max_real_part,verdict");
  // C = 3 > A + B = 2.5 violates the triangle inequality: reported, not computed.
  EXPECT_NE(rows.back().find("nonphysical"), std::string::npos) << rows.back();
}

TEST(StabilityCli, BadInputIsOneLineAndExitCodeTwo) {
  // The initial state of this example is not an equilibrium: the message gives the residual.
  CliResult r = newtop("stability " + example("equilibria_newtonian.toml"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("found residual"), std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1);
  r = newtop("stability " + example("stability_beletsky.toml") + " --axis w --omega 1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--axis: expected x, y or z, found 'w'"), std::string::npos) << r.out;
  r = newtop("stability " + example("stability_beletsky.toml") + " --scan-omega 0:3");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--scan-omega: expected LO:HI:N"), std::string::npos) << r.out;
  r = newtop("stability " + example("rotation_staude_cone.toml") + " --axis z --omega 1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("not along the axis"), std::string::npos) << r.out;
}

TEST(StabilityCli, EquilibriumOptionAnalysesTheListedEquilibrium) {
  // --equilibrium K is the K-th (1-based) entry of newtop equilibria, whose "index" says K.
  const std::string file = example("equilibria_newtonian.toml");
  const auto list = io::Json::parse(newtop("equilibria " + file + " --json").out)["equilibria"];
  ASSERT_EQ(list.size(), 6u);
  for (std::size_t k = 1; k <= list.size(); ++k) {
    const io::Json& e = list[k - 1];
    EXPECT_EQ(e["index"].get<std::size_t>(), k);
    const CliResult r = newtop("stability " + file + " --json --equilibrium " + std::to_string(k));
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = io::Json::parse(r.out);
    EXPECT_EQ(j["equilibrium"].get<std::size_t>(), k);
    const auto g = j["gamma"].get<std::vector<double>>(),
               ge = e["gamma"].get<std::vector<double>>();
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(g[i], ge[i], 1e-15) << "K = " << k;
    EXPECT_EQ(j["omega"], io::Json::parse("[0.0, 0.0, 0.0]"));
    // At rest: a minimum of V is Lyapunov stable, a saddle or a maximum unstable.
    const bool minimum = e["type"] == "minimum";
    EXPECT_EQ(j["linearly_stable"].get<bool>(), minimum) << "K = " << k;
    EXPECT_EQ(j["lyapunov_stable"], minimum) << "K = " << k;
  }
  // 0 is no equilibrium number at all (the option's range, docs/cli.md); 7 is beyond the list.
  {
    const CliResult r = newtop("stability " + file + " --equilibrium 0");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.out.find("--equilibrium: expected an integer from 1 to 1000000, found 0"),
              std::string::npos)
        << r.out;
  }
  {
    const CliResult r = newtop("stability " + file + " --equilibrium 7");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.out.find("--equilibrium: expected 1 to 6 (the equilibria listed by newtop "
                         "equilibria), found 7"),
              std::string::npos)
        << r.out;
  }
  CliResult r = newtop("stability " + file + " --equilibrium 1 --axis z");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--equilibrium: give either --equilibrium or --axis"), std::string::npos);
}

TEST(StabilityCli, StateCopiedToSevenDigitsIsPolished) {
  // The second equilibrium of equilibria_newtonian.toml copied to 7 significant digits: its
  // residual (~1e-7) is far above kFixedPointTolerance; Newton's method restores it and reports
  // the correction, which is the size of the rounding.
  const std::string file = example("equilibria_newtonian.toml");
  const auto e = io::Json::parse(newtop("equilibria " + file + " --json").out)["equilibria"][1];
  const auto g = e["gamma"].get<std::vector<double>>();
  char gamma[128];
  std::snprintf(gamma, sizeof gamma, "[%.7g, %.7g, %.7g]", g[0], g[1], g[2]);
  const fs::path toml = temp_file("copy.toml");
  std::ofstream(toml) << "[body]\ninertia = [1.0, 1.6, 2.1]\nmass = 1.0\n"
                         "center_of_mass = [0.05, -0.03, 0.02]\n"
                         "[field]\ng = 1.0\nlambda = 1.0\n"
                         "[initial]\nnormalize = true\nomega = [0.0, 0.0, 0.0]\ngamma = "
                      << gamma << "\n";
  CliResult r = newtop("stability " + toml.string() + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = io::Json::parse(r.out);
  const double given = j["polish"]["residual_given"].get<double>();
  const double correction = j["polish"]["correction"].get<double>();
  EXPECT_GT(given, kFixedPointTolerance);
  EXPECT_GT(correction, 1e-10);  // 7 digits: the rounding is up to 5e-7 per component …
  EXPECT_LT(correction, 1e-6);   // … and so is the correction
  EXPECT_LE(j["residual"].get<double>(), 64 * std::numeric_limits<double>::epsilon());
  const auto gp = j["gamma"].get<std::vector<double>>();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(gp[i], g[i], 1e-14);
  EXPECT_EQ(j["linearly_stable"], e["type"] == "minimum");
  // The human summary says so.
  r = newtop("stability " + toml.string());
  EXPECT_NE(r.out.find("polished  by Newton's method: correction"), std::string::npos) << r.out;
  // A tumbling state is refused: no fixed point within kPolishRadius.
  std::ofstream(toml) << "[body]\ninertia = [1.0, 1.6, 2.1]\nmass = 1.0\n"
                         "center_of_mass = [0.05, -0.03, 0.02]\n"
                         "[field]\ng = 1.0\nlambda = 1.0\n"
                         "[initial]\nomega = [0.1, 0.2, 0.3]\ngamma = [0.6, 0.0, 0.8]\n";
  r = newtop("stability " + toml.string());
  fs::remove(toml);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("expected an equilibrium or a permanent rotation"), std::string::npos)
      << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1);
}

TEST(StabilityCli, ScanOmegaIsPrintedInTheSummary) {
  // Without --out or --json the diagram is a table in the summary: a header and one row per Ω.
  const CliResult r =
      newtop("stability " + example("stability_beletsky.toml") + " --scan-omega 0:3:7");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto at = r.out.find("Omega                    max real part");
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.out.begin() + static_cast<long>(at), r.out.end(), '\n'), 8) << r.out;
  // --out without a diagram to write is bad input, not a file silently never written.
  const CliResult o =
      newtop("stability " + example("stability_beletsky.toml") + " --out never.csv");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.out.find("--out: needs --scan-omega or --scan"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists("never.csv"));
}

TEST(StabilityCli, RequestsBeyondTheDocumentedBoundsAreBadInput) {
  CliResult r =
      newtop("rotations " + example("rotation_staude_cone.toml") + " --samples 2000000000");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("samples: expected an integer from 2 to 100000"), std::string::npos)
      << r.out;
  r = newtop("stability " + example("stability_beletsky.toml") + " --scan-omega 0:3:2000000000");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("a count from 1 to 100000"), std::string::npos) << r.out;
  r = newtop("stability " + example("stability_beletsky.toml") +
             " --scan omega=0:3:10000,C=1:3:1000 --out never.csv");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--scan: expected at most 1000000 grid points"), std::string::npos) << r.out;
  // The library enforces the same bounds.
  const QuadraticModel m =
      io::load_scenario(example("rotation_staude_cone.toml")).model.quadratic();
  EXPECT_THROW(permanent_rotations(m, kMaxRotationSamples + 1), InputError);
  EXPECT_NO_THROW(permanent_rotations(m, 2));
  EXPECT_THROW(scan_omega(m, 2, 0.0, 1.0, kMaxScanPoints + 1), InputError);
}

TEST(StabilityCli, UniformGravityAndRotorCases) {
  // Uniform gravity with r0 = 0: every orientation; a rotor (k ≠ 0) is outside docs/model.md §8.
  const fs::path toml = temp_file("rotor.toml");
  std::ofstream(toml) << "[body]\ninertia = [1.0, 1.5, 2.0]\ngyrostat = [0.0, 0.0, 0.3]\n"
                         "[field]\nkind = \"uniform\"\ng = 9.81\n"
                         "[initial]\nomega = [0.0, 0.0, 0.0]\ngamma = [0.0, 0.0, 1.0]\n";
  CliResult r = newtop("equilibria " + toml.string() + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = io::Json::parse(r.out);
  EXPECT_TRUE(j["every_orientation"].get<bool>());
  EXPECT_EQ(j["count"].get<int>(), 0);
  r = newtop("rotations " + toml.string());
  fs::remove(toml);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("gyrostat: permanent rotations"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace test_cli_test
}  // namespace newtop
