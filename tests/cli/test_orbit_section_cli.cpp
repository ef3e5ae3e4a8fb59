// newtop section on orbit scenarios end to end: the JSON keys (with `normal` and the orbital-frame
// coordinates), the CSV header, the Jacobi integral and Casimirs in the drift, the elliptic orbit,
// and the bad combinations refused in one line before any work.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace test_orbit_section_cli {
namespace {

namespace fs = std::filesystem;
using newtop::test::CliResult;

CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::string leo() { return newtop::test::example_path("orbit_leo_lagrange.toml"); }
std::string pitch() { return newtop::test::example_path("orbit_elliptic_pitch.toml"); }

fs::path scratch(const std::string& name) {
  return newtop::test::scratch_path("newtop_orbit_section", name);
}

TEST(OrbitSectionCli, CircularJsonContract) {
  const CliResult r = run("section " + leo() + " --surface 'gamma2 = 0' --crossings 3 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["surface"], "gamma2 = 0");
  EXPECT_EQ(j["count"], 3);
  EXPECT_EQ(j["stopped_by"], "crossings");
  EXPECT_EQ(j["orbit"], "circular");
  EXPECT_LT(j["max_surface_residual"].get<double>(), 1e-16);
  ASSERT_EQ(j["crossings"].size(), 3u);
  for (const auto& c : j["crossings"]) {
    for (const char* k : {"omega", "gamma", "m", "normal"}) EXPECT_EQ(c[k].size(), 3u) << k;
    EXPECT_EQ(c["coords"]["euler_321"].size(), 3u);
    EXPECT_EQ(c["coords"]["omega_relative"].size(), 3u);
    EXPECT_FALSE(c.contains("nu"));
  }
  // The Jacobi integral (3.9e-5 J, splitting6 at ω0h = 0.011) and the Casimirs: see
  // example.conservation.orbit_leo_lagrange for the derivation of the bound.
  EXPECT_LT(j["integrals_drift"]["jacobi"].get<double>(), 1.2e-16);
  for (const char* k : {"gamma_gamma", "normal_normal", "gamma_normal"}) {
    EXPECT_LT(j["integrals_drift"][k].get<double>(), 1e-12) << k;
  }
}

TEST(OrbitSectionCli, EllipticCsvHasTheAnomaly) {
  const fs::path csv = scratch("pitch.csv");
  const CliResult r = run("section " + pitch() + " --surface 'gamma2 = 0' --direction both --out " +
                          csv.string() + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["orbit"], "elliptic");
  EXPECT_EQ(j["stopped_by"], "t_end");
  EXPECT_FALSE(j["integrals_drift"].contains("jacobi"));
  ASSERT_GT(j["count"].get<int>(), 4);
  EXPECT_TRUE(j["crossings"][0].contains("nu"));
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header,
            "orbit,t,nu,p,q,r,gamma1,gamma2,gamma3,normal1,normal2,normal3,psi,theta,phi,"
            "omega_rel1,omega_rel2,omega_rel3,roll,pitch,yaw");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, j["count"].get<int>());
  fs::remove_all(csv.parent_path());
}

// Bad input: exit 2, one line on stderr naming the field, before any work (no output file).
TEST(OrbitSectionCli, BadCombinationsAreOneLineBeforeWork) {
  const fs::path csv = scratch("never.csv");
  const std::string brun = newtop::test::example_path("brun.toml");
  const std::vector<std::pair<std::string, std::string>> cases{
      {leo() + " --surface 'normal4 = 0'", "--surface: expected a component"},
      {leo() + " --surface 'gamma2 = 0' --orbits 4", "--orbits: expected a body scenario"},
      {leo() + " --surface 'gamma2 = 0' --method rk4", "method: expected one of"},
      {leo() + " --surface 'gamma2 = 0' --t-end -1", "t_end: expected a finite time"},
      {leo() + " --surface 'gamma2 = 0' --direction sideways", "--direction"},
      {brun + " --surface 'normal3 = 0'", "normal1..3, the orbit normal, only on an orbit"}};
  for (const auto& [args, message] : cases) {
    const CliResult r = run("section " + args + " --out " + csv.string());
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_FALSE(fs::exists(csv)) << args;
  }
  // chaos on an orbit refuses the scenario's splitting (it has no tangent map there), saying so.
  const CliResult c = run("chaos " + leo());
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("expected rkf78, dopri5, dop853 or taylor"), std::string::npos) << c.err;
}

}  // namespace
}  // namespace test_orbit_section_cli
