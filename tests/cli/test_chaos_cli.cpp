// newtop chaos end to end: the JSON keys of the issue, the history CSV, bad input in one line.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace test_chaos_cli {
namespace {

namespace fs = std::filesystem;
using newtop::test::CliResult;

CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::string brun() { return newtop::test::example_path("brun.toml"); }

TEST(ChaosCli, JsonContract) {
  const CliResult r = run("chaos " + brun() + " --t-end 20 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* k :
       {"lyapunov_max", "spectrum", "megno", "fli", "t_end", "method", "step", "outcome"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  EXPECT_TRUE(j["spectrum"].is_null());
  EXPECT_EQ(j["t_end"], 20.0);
  EXPECT_EQ(j["method"], "splitting6");
  EXPECT_EQ(j["step"], 0.01);
  EXPECT_EQ(j["outcome"], "finished");
  const CliResult s = run("chaos " + brun() + " --t-end 20 --spectrum --method rk4 --json");
  ASSERT_EQ(s.code, 0) << s.err;
  const auto js = nlohmann::json::parse(s.out);
  EXPECT_EQ(js["spectrum"].size(), 6u);
  EXPECT_EQ(js["method"], "rk4");
  EXPECT_EQ(js["spectrum"][0], js["lyapunov_max"]);
  EXPECT_FALSE(js.contains("split"));  // not a splitting method
}

// --split spin runs the spin split's own tangent map (the JSON says which split): the same
// exponent as the axes split within 1% at T = 50 (another map of the same flow); --split exact
// has no tangent map: one line naming split, exit 2.
TEST(ChaosCli, SpinSplitHasATangentMap) {
  const CliResult axes = run("chaos " + brun() + " --t-end 50 --json");
  const CliResult spin = run("chaos " + brun() + " --t-end 50 --split spin --json");
  ASSERT_EQ(axes.code, 0) << axes.err;
  ASSERT_EQ(spin.code, 0) << spin.err;
  const auto ja = nlohmann::json::parse(axes.out), js = nlohmann::json::parse(spin.out);
  EXPECT_EQ(ja["split"], "axes");
  EXPECT_EQ(js["split"], "spin");
  const double la = ja["lyapunov_max"], ls = js["lyapunov_max"];
  EXPECT_NEAR(ls, la, 0.01 * la);
  EXPECT_NE(ls, la);  // a different map reached the run
  const CliResult exact = run("chaos " + brun() + " --t-end 5 --split exact");
  EXPECT_EQ(exact.code, 2);
  EXPECT_NE(exact.err.find("split"), std::string::npos) << exact.err;
  EXPECT_EQ(std::count(exact.err.begin(), exact.err.end(), '\n'), 1) << exact.err;
}

// The adaptive methods integrate the variational equations: "step" is null and "tol" given; with a
// tolerance alone, Taylor's method on the quadratic field (as for simulate).
TEST(ChaosCli, AdaptiveMethod) {
  const CliResult r = run("chaos " + brun() + " --t-end 20 --tol 1e-10 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"], "taylor");
  EXPECT_TRUE(j["step"].is_null());
  EXPECT_EQ(j["tol"], 1e-10);
  const CliResult d = run("chaos " + brun() + " --t-end 20 --tol 1e-10 --method dop853 --json");
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_EQ(nlohmann::json::parse(d.out)["method"], "dop853");
}

TEST(ChaosCli, HistoryCsv) {
  const fs::path csv = newtop::test::scratch_path("newtop_chaos", "history.csv");
  const CliResult r = run("chaos " + brun() + " --t-end 5 --spectrum --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header,
            "t,lyapunov_max,megno_y,megno,fli,lambda1,lambda2,lambda3,lambda4,lambda5,lambda6");
  int rows = 0;
  std::string last;
  for (std::string line; std::getline(in, line);) {
    ++rows;
    last = line;
  }
  EXPECT_EQ(rows, 500);  // every step of 500
  EXPECT_EQ(last.substr(0, 2), "5,");
  fs::remove(csv);
}

TEST(ChaosCli, BadInputIsOneLineBeforeWork) {
  const fs::path csv = newtop::test::scratch_path("newtop_chaos", "never.csv");
  for (const std::string args : {"--tol -1", "--method dopri5 --step 0.1", "--step -1",
                                 "--step 0.1 --tol 1e-9", "--t-end 0", "--method nope"}) {
    const CliResult r = run("chaos " + brun() + " " + args + " --out " + csv.string());
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(csv)) << args;
  }
}

}  // namespace
}  // namespace test_chaos_cli
