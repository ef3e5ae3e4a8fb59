// The equilibria, rotations and stability commands: JSON keys, CSV files, bad input.

#include "support/cli.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/rotations.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop {
namespace {

namespace fs = std::filesystem;

using test::CliResult;
using test::example_path;

/// Runs `newtop ARGS` with stderr merged into the output.
CliResult newtop(const std::string& args) { return test::run_newtop(args); }

std::string example(const std::string& name) { return example_path(name); }

fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() /
         ("newtop_stability_" + std::to_string(::getpid()) + "_" + name);
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
  const Model model = io::load_scenario(file).model;
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
  const Body body = io::load_scenario(file).model.body;
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

TEST(StabilityCli, UniformGravityAndRotorCases) {
  // Uniform gravity with r0 = 0: every orientation; a rotor (k ≠ 0) is outside spec §8.
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
}  // namespace newtop
