// The program on orbit scenarios: JSON contracts of simulate, equilibria and stability, the
// DeBra–Delp diagram, and bad orbit input as one line with exit 2.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace test_orbit_cli {
namespace {

namespace fs = std::filesystem;
using newtop::test::CliResult;

CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::string example(const char* name) { return newtop::test::example_path(name); }

fs::path scratch(const std::string& name) {
  return newtop::test::scratch_path("newtop_orbit_cli", name);
}

void expect_one_line_error(const CliResult& r, const char* part) {
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("newtop: error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

// Ten orbits of a librating satellite with splitting6: the Jacobi integral stays at its
// round-off level (|H| ≈ 4e-5, ε|H| per step over 5560 steps: < 1e-15) and the Casimirs too.
TEST(OrbitCli, SimulateJsonHasNormalAndKeepsTheIntegrals) {
  const CliResult r = run("simulate " + example("orbit_leo_lagrange.toml") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "finished");
  EXPECT_EQ(j["final"]["t"], 55600.0);
  EXPECT_EQ(j["final"]["normal"].size(), 3u);
  EXPECT_LT(j["integrals"]["max_abs_drift"]["jacobi"].get<double>(), 1e-15);
  EXPECT_LT(j["integrals"]["max_abs_drift"]["casimir_error"].get<double>(), 1e-12);
  EXPECT_EQ(j["model"]["orbit"]["kind"], "circular");
}

TEST(OrbitCli, EllipticSimulateEndsAtTheRequestedTime) {
  const fs::path csv = scratch("pitch.csv");
  const CliResult r = run("simulate " + example("orbit_elliptic_pitch.toml") + " --t-end 3 --out " +
                          csv.string() + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["final"]["t"].get<double>(), 3.0, 1e-12);  // ν(t) by Kepler, back to t
  EXPECT_TRUE(j["final"].contains("nu"));
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header,
            "t,nu,omega1,omega2,omega3,gamma1,gamma2,gamma3,normal1,normal2,normal3,"
            "hamiltonian_nu,casimir_error");
}

TEST(OrbitCli, EquilibriaListsTwentyFourWithStability) {
  const CliResult r = run("equilibria " + example("orbit_debra_delp.toml") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["count"], 24);
  EXPECT_EQ(j["lyapunov"], 4);
  EXPECT_EQ(j["gyroscopic"], 4);
  for (const auto& e : j["equilibria"]) {
    for (const char* k : {"gamma", "normal", "jacobi", "linearly_stable", "lyapunov_stable",
                          "eigenvalues", "max_real_part"}) {
      EXPECT_TRUE(e.contains(k)) << k;
    }
  }
}

TEST(OrbitCli, StabilityVerdicts) {
  const CliResult g = run("stability " + example("orbit_debra_delp.toml") + " --json");
  ASSERT_EQ(g.code, 0) << g.err;
  const auto jg = nlohmann::json::parse(g.out);
  EXPECT_EQ(jg["linearly_stable"], true);
  EXPECT_TRUE(jg["lyapunov_stable"].is_null());
  EXPECT_EQ(jg["verdict"], "gyroscopic");
  const CliResult l = run("stability " + example("orbit_leo_lagrange_rest.toml") + " --json");
  ASSERT_EQ(l.code, 0) << l.err;
  EXPECT_EQ(nlohmann::json::parse(l.out)["lyapunov_stable"], true);
  // A librating state is not a relative equilibrium.
  expect_one_line_error(run("stability " + example("orbit_leo_lagrange.toml")),
                        "relative equilibrium");
}

TEST(OrbitCli, DebraDelpDiagram) {
  const fs::path csv = scratch("dd.csv");
  const CliResult r =
      run("stability --diagram debra-delp --scan k_R=-0.5:0.5:5,k_Y=-0.5:0.5:4 "
          "--out " +
          csv.string() + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"].size(), 20u);
  EXPECT_EQ(j["disagreements_with_closed_form"], 0);
  std::ifstream in(csv);
  int lines = 0;
  for (std::string s; std::getline(in, s);) ++lines;
  EXPECT_EQ(lines, 21);
  const fs::path bad = scratch("bad.csv");
  expect_one_line_error(run("stability --diagram debra-delp --scan k_R=-0.5:1.5:5,k_Y=0:0.5:4 "
                            "--out " +
                            bad.string()),
                        "--scan");
  EXPECT_FALSE(fs::exists(bad));
  expect_one_line_error(run("stability --diagram lagrange"), "--diagram");
  expect_one_line_error(run("stability --diagram debra-delp " + example("orbit_debra_delp.toml")),
                        "--diagram");
}

TEST(OrbitCli, BadOrbitInputIsOneLine) {
  const fs::path f = scratch("bad_orbit.toml");
  std::ofstream(f) << "[body]\ninertia = [1.0, 1.6, 2.1]\n[orbit]\nkind = \"elliptic\"\n"
                      "mu = 1.0\nsemi_major_axis = 1.0\neccentricity = 1.2\n"
                      "[initial]\nquaternion = [1.0, 0.0, 0.0, 0.0]\n";
  for (const char* cmd : {"simulate", "integrals", "equilibria", "stability"}) {
    expect_one_line_error(run(std::string(cmd) + " " + f.string() + " --json"), "eccentricity");
  }
  expect_one_line_error(run("equilibria " + example("orbit_elliptic_pitch.toml")), "circular");
  expect_one_line_error(run("simulate " + example("orbit_leo_lagrange.toml") + " --method rk4"),
                        "method");
}

}  // namespace
}  // namespace test_orbit_cli
