// The newtop program end to end: JSON and CSV contracts, exit codes, one-line errors, no partial
// output files.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace {

namespace fs = std::filesystem;

using newtop::test::CliResult;

// Standard error is kept apart: the tests count its lines and parse standard output as JSON.
CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::string example(const char* name) { return newtop::test::example_path(name); }

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("newtop_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path p = scratch(name);
  std::ofstream(p) << text;
  return p;
}

TEST(Cli, SimulateJsonContract) {
  const CliResult r = run("simulate " + example("brun.toml") + " --t-end 5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["final"]["t"], 5.0);
  EXPECT_EQ(j["final"]["omega"].size(), 3u);
  EXPECT_EQ(j["final"]["gamma"].size(), 3u);
  for (const char* k : {"energy", "area", "geometric", "brun"}) {
    EXPECT_TRUE(j["integrals"]["initial"].contains(k)) << k;
    EXPECT_TRUE(j["integrals"]["final"].contains(k)) << k;
    EXPECT_TRUE(j["integrals"]["max_abs_drift"].contains(k)) << k;
  }
  EXPECT_FALSE(j["integrals"]["initial"].contains("lagrange"));
  EXPECT_EQ(j["steps"], 500);
  EXPECT_EQ(j["method"], "splitting6");
  EXPECT_EQ(j["outcome"], "finished");
  // The drift reported is the drift measured: a splitting method keeps it at round-off.
  EXPECT_LT(j["integrals"]["max_abs_drift"]["geometric"].get<double>(), 1e-14);
}

TEST(Cli, ToleranceSelectsAdaptiveAndMethodOverrides) {
  const CliResult r = run("simulate " + example("brun.toml") + " --t-end 1 --tol 1e-9 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["method"], "rkf78");
  const CliResult r2 =
      run("simulate " + example("brun.toml") + " --t-end 1 --tol 1e-9 --method dopri5 --json");
  ASSERT_EQ(r2.code, 0) << r2.err;
  EXPECT_EQ(nlohmann::json::parse(r2.out)["method"], "dopri5");
}

TEST(Cli, IntegralsJson) {
  const CliResult r = run("integrals " + example("lagrange_like.toml") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["conserved"], nlohmann::json::array({"energy", "area", "geometric", "lagrange"}));
  EXPECT_EQ(j["integrals"]["lagrange"], 1.2 * 4.0);  // C r + k3 with k = 0
}

TEST(Cli, CsvColumnsAndRows) {
  const fs::path csv = scratch("traj.csv");
  const CliResult r = run("simulate " + example("lagrange_like.toml") +
                          " --t-end 1 --step 0.01 --every 10 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "t,p,q,r,gamma1,gamma2,gamma3,energy,area,geometric,lagrange");
  int rows = 0;
  std::string last;
  while (std::getline(in, line)) {
    ++rows;
    last = line;
  }
  EXPECT_EQ(rows, 11);  // t = 0, 0.1, …, 1.0
  EXPECT_EQ(last.substr(0, 2), "1,");
}

TEST(Cli, BadInputIsOneLineAndExitCodeTwo) {
  const std::string good =
      "[body]\ninertia = [1.0, 1.5, 2.2]\n[field]\ng = 1.0\nlambda = 0.5\n"
      "[initial]\nomega = [0.1, 0.2, 0.3]\ngamma = [0.0, 0.0, 1.0]\n"
      "[integrate]\nt_end = 1.0\nstep = 0.1\n";
  struct Case {
    std::string from, to, names;
  };
  const Case cases[] = {
      {"inertia = [1.0, 1.5, 2.2]", "inertia = [1.0, 1.5, 9.0]", "[body] inertia: triangle"},
      {"g = 1.0", "gg = 1.0", "[field] gg: unknown key"},
      {"step = 0.1", "step = \"big\"", "[integrate] step: expected a number"},
      {"gamma = [0.0, 0.0, 1.0]", "gamma = [0.0, 1.0]", "[initial] gamma: expected an array of 3"},
      {"lambda = 0.5", "lambda = nan", "[field] lambda: expected a finite number"},
      {"[body]", "[body", "malformed TOML"},
  };
  for (const auto& [from, to, names] : cases) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    const fs::path f = write_file("bad.toml", text);
    const fs::path csv = scratch("never.csv");
    const CliResult r = run("simulate " + f.string() + " --out " + csv.string());
    EXPECT_EQ(r.code, 2) << to;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(csv)) << "partial output left for " << to;
  }
  const CliResult missing = run("simulate /nonexistent/none.toml");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos);
  const CliResult bad_flag = run("simulate " + example("brun.toml") + " --step -1");
  EXPECT_EQ(bad_flag.code, 2) << bad_flag.err;
}

TEST(Cli, UnwritableOutputLeavesNothing) {
  const CliResult r = run("simulate " + example("brun.toml") + " --out /nonexistent/dir/x.csv");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("x.csv"), std::string::npos);
}

TEST(Cli, NonFiniteOutcomeExitsThreeWithCompleteFile) {
  const std::string text =
      "[body]\ninertia = [1.0, 1.5, 2.2]\n[field]\ng = 1.0\nlambda = 0.5\n"
      "[initial]\nomega = [1000.0, -2000.0, 500.0]\ngamma = [0.0, 0.0, 1.0]\n"
      "[integrate]\nt_end = 1e6\nstep = 10.0\nmethod = \"rk4\"\n";
  const fs::path f = write_file("blowup.toml", text);
  const fs::path csv = scratch("blowup.csv");
  const CliResult r = run("simulate " + f.string() + " --json --out " + csv.string());
  EXPECT_EQ(r.code, 3);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "non_finite");
  EXPECT_TRUE(fs::exists(csv));
  std::ifstream in(csv);
  std::string all((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(all.find("nan"), std::string::npos);
  EXPECT_EQ(all.back(), '\n');
}

}  // namespace
