// newtop section end to end: the JSON keys and CSV header of the issue, bad surfaces and options
// rejected in one line before any work, empty levels reported.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace test_section_cli {
namespace {

namespace fs = std::filesystem;
using newtop::test::CliResult;

CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::string brun() { return newtop::test::example_path("brun.toml"); }

fs::path scratch(const std::string& name) {
  return newtop::test::scratch_path("newtop_section", name);
}

TEST(SectionCli, JsonContract) {
  const CliResult r = run("section " + brun() + " --surface 'gamma3 = 0' --crossings 4 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* k : {"surface", "direction", "crossings", "count", "stopped_by",
                        "max_surface_residual", "integrals_drift"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  EXPECT_EQ(j["surface"], "gamma3 = 0");
  EXPECT_EQ(j["direction"], "up");
  EXPECT_EQ(j["count"], 4);
  EXPECT_EQ(j["stopped_by"], "crossings");
  ASSERT_EQ(j["crossings"].size(), 4u);
  for (const auto& c : j["crossings"]) {
    EXPECT_EQ(c["orbit"], 0);
    EXPECT_EQ(c["omega"].size(), 3u);
    EXPECT_EQ(c["gamma"].size(), 3u);
    EXPECT_EQ(c["m"].size(), 3u);
    for (const char* k : {"l", "L_over_G", "g", "G", "gamma1", "gamma2", "p_gamma1", "p_gamma2"}) {
      EXPECT_TRUE(c["coords"].contains(k)) << k;
    }
    EXPECT_EQ(c["coords"]["gamma1"], c["gamma"][0]);
  }
  for (const char* k : {"energy", "area", "geometric", "brun"}) {
    EXPECT_TRUE(j["integrals_drift"].contains(k)) << k;
  }
  const CliResult t = run("section " + brun() + " --surface 'gamma3 = 0' --t-end 5 --json");
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_EQ(nlohmann::json::parse(t.out)["stopped_by"], "t_end");
}

TEST(SectionCli, CsvHeaderAndRows) {
  const fs::path csv = scratch("s.csv");
  const CliResult r =
      run("section " + brun() + " --surface 'gamma3 = 0' --orbits 3 --crossings 5 " + "--out " +
          csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "orbit,t,p,q,r,gamma1,gamma2,gamma3,l,L_over_G,g,G,p_gamma1,p_gamma2");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 15);
  const fs::path csv2 = scratch("s2.csv");
  ASSERT_EQ(
      run("section " + brun() + " --surface 'omega1 = 0' --t-end 10 --out " + csv2.string()).code,
      0);
  std::ifstream in2(csv2);
  std::getline(in2, header);
  EXPECT_EQ(header, "orbit,t,p,q,r,gamma1,gamma2,gamma3,l,L_over_G,g,G");
}

// Bad input: exit 2, one line on stderr naming the field, before any work (no output file).
TEST(SectionCli, BadInputIsOneLineBeforeWork) {
  const fs::path csv = scratch("never.csv");
  for (const std::string args :
       {"--surface 'gamma4 = 0'", "--surface 'gamma3'",
        "--surface 'gamma3 = 0' --direction sideways", "--surface 'gamma3 = 0' --crossings 0",
        "--surface 'gamma3 = 0' --orbits 0", "--surface 'gamma3 = 0' --step 0.01 --tol 1e-9",
        "--surface 'gamma3 = 0' --step -1", "--surface 'gamma3 = 0' --energy 1",
        "--surface 'gamma3 = 0' --method nope"}) {
    const CliResult r = run("section " + brun() + " " + args + " --out " + csv.string());
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_FALSE(fs::exists(csv)) << args;
  }
  const CliResult r = run("section " + brun() + " --surface 'gamma1 + 0.5 gamma2 = 0.1'");
  EXPECT_NE(r.err.find("--surface: expected '*'"), std::string::npos) << r.err;
}

TEST(SectionCli, EmptyLevelIsReported) {
  const CliResult r =
      run("section " + brun() + " --surface 'gamma3 = 0' --orbits 6 --energy -5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["count"], 0);
  EXPECT_EQ(j["levels"]["empty"], true);
  EXPECT_EQ(j["levels"]["orbits"], 0);
  EXPECT_NE(r.err.find("does not meet the surface"), std::string::npos);
  const CliResult ok = run("section " + brun() + " --surface 'gamma3 = 0' --orbits 6 --json");
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_EQ(nlohmann::json::parse(ok.out)["levels"]["orbits"], 6);
}

}  // namespace
}  // namespace test_section_cli
