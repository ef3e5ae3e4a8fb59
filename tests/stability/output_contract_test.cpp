// Output contracts every subcommand shares (docs/cli.md): CSV booleans are 1/0 and no cell is
// empty; no number is printed as −0; a human summary never prints "null".

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_output_contract_test {
namespace {

namespace fs = std::filesystem;
using test::CliResult;
using test::example_path;

CliResult newtop(const std::string& args) { return test::run_newtop(args); }

fs::path temp_file(const std::string& name) {
  return newtop::test::scratch_path("newtop_contract", name);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
  if (!line.empty() && line.back() == ',') cells.emplace_back();  // a trailing empty cell
  return cells;
}

/// Checks a CSV file against the convention: a header, the same number of cells on every row,
/// no empty cell, the named boolean columns 1 or 0, the named word columns one of `words`, and
/// every other cell a number that strtod reads whole (nan where a value does not exist).
void expect_csv_convention(const fs::path& path, const std::set<std::string>& booleans,
                           const std::set<std::string>& word_columns = {},
                           const std::set<std::string>& words = {}) {
  std::ifstream in(path);
  std::string line;
  ASSERT_TRUE(std::getline(in, line)) << path;
  const std::vector<std::string> header = split(line);
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    const std::vector<std::string> cells = split(line);
    ASSERT_EQ(cells.size(), header.size()) << path << ": " << line;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::string& c = cells[i];
      ASSERT_FALSE(c.empty()) << path << ": empty " << header[i] << " in " << line;
      if (booleans.count(header[i])) {
        EXPECT_TRUE(c == "0" || c == "1") << path << ": " << header[i] << " = " << c;
      } else if (word_columns.count(header[i])) {
        EXPECT_TRUE(words.count(c)) << path << ": " << header[i] << " = " << c;
      } else {
        char* end = nullptr;
        std::strtod(c.c_str(), &end);
        EXPECT_EQ(*end, '\0') << path << ": " << header[i] << " = " << c;
      }
    }
  }
  EXPECT_GT(rows, 0) << path;
}

TEST(OutputContract, EveryCsvWriterUsesOneZeroBooleansAndNoEmptyCell) {
  const fs::path csv = temp_file("convention.csv");
  const std::string beletsky = example_path("stability_beletsky.toml");
  // Stability along Ω: inconclusive points (Ω* < Ω < 1) and unstable ones both occur in 0:3.
  CliResult r = newtop("stability " + beletsky + " --scan-omega 0:3:61 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.out;
  expect_csv_convention(csv, {"linearly_stable", "energy_casimir_stable"});
  // The two-parameter diagram, with non-physical moments (C > A + B) in the grid.
  r = newtop("stability " + beletsky + " --scan omega=0:3:5,C=1:3:4 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.out;
  expect_csv_convention(csv, {}, {"verdict"}, {"stable", "unstable", "nonphysical"});
  // The Staude cone.
  r = newtop("rotations " + example_path("rotation_staude_cone.toml") + " --samples 20 --out " +
             csv.string());
  ASSERT_EQ(r.code, 0) << r.out;
  expect_csv_convention(csv, {"admissible"});
  // The trajectory.
  r = newtop("simulate " + example_path("brun.toml") + " --t-end 1 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.out;
  expect_csv_convention(csv, {});
  fs::remove(csv);
}

TEST(OutputContract, ScanOmegaCsvMatchesTheJsonVerdicts) {
  // energy_casimir_stable = 1 exactly where the JSON says lyapunov_stable true; linearly_stable
  // as in the JSON.
  const fs::path csv = temp_file("scan.csv");
  const CliResult r = newtop("stability " + example_path("stability_beletsky.toml") +
                             " --json --scan-omega 0:3:61 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto scan = io::Json::parse(r.out)["scan"];
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "omega,max_real_part,linearly_stable,energy_casimir_stable");
  int inconclusive = 0;
  for (const auto& p : scan) {
    ASSERT_TRUE(std::getline(in, line));
    const auto cells = split(line);
    EXPECT_EQ(cells[2], p["linearly_stable"].get<bool>() ? "1" : "0") << line;
    EXPECT_EQ(cells[3], p["lyapunov_stable"] == true ? "1" : "0") << line;
    inconclusive += p["lyapunov_stable"].is_null();
  }
  EXPECT_GT(inconclusive, 0);  // the case a three-valued column would have left empty
  fs::remove(csv);
}

/// A −0 written as a number: "-0" or "-0.0…" not followed by another digit.
bool has_negative_zero(const std::string& text) {
  static const std::regex negative_zero("(^|[^0-9.eE])-0(\\.0*)?([^0-9.eE]|$)");
  return std::regex_search(text, negative_zero);
}

TEST(OutputContract, NoNegativeZeroInAnyOutput) {
  EXPECT_TRUE(has_negative_zero("g = -0   lambda"));
  EXPECT_TRUE(has_negative_zero("[-0.0, -1.0, -0.0]"));
  EXPECT_FALSE(has_negative_zero("-0.5, 1e-07, -0.05, 10"));
  // brun.toml: g = −N·0 is −0; the principal axes of a body with r0 = 0 include −e_y, whose
  // components are −0; stability_beletsky.toml has r0 = 0.
  const std::string brun = example_path("brun.toml");
  const std::string beletsky = example_path("stability_beletsky.toml");
  for (const std::string& args :
       {"simulate " + brun + " --t-end 1", "simulate " + brun + " --t-end 1 --json",
        "integrals " + brun, "integrals " + brun + " --json", "equilibria " + brun,
        "equilibria " + brun + " --json", "rotations " + beletsky,
        "rotations " + beletsky + " --json", "stability " + beletsky,
        "stability " + beletsky + " --json", "stability " + beletsky + " --axis x --omega 0",
        "stability " + beletsky + " --axis y --omega 0 --json"}) {
    const CliResult r = newtop(args);
    ASSERT_EQ(r.code, 0) << args << "\n" << r.out;
    EXPECT_FALSE(has_negative_zero(r.out)) << args << "\n" << r.out;
  }
}

TEST(OutputContract, HumanSummaryNeverPrintsNull) {
  // Spins whose thresholds do not exist (least and middle axis) and a scan without --out.
  const std::string beletsky = example_path("stability_beletsky.toml");
  for (const std::string& args : {"stability " + beletsky + " --axis x --omega 0.5",
                                  "stability " + beletsky + " --axis y --omega 2",
                                  "stability " + beletsky + " --scan-omega 0:3:7"}) {
    const CliResult r = newtop(args);
    ASSERT_EQ(r.code, 0) << args << "\n" << r.out;
    EXPECT_EQ(r.out.find("null"), std::string::npos) << args << "\n" << r.out;
  }
}

}  // namespace
}  // namespace test_output_contract_test
}  // namespace newtop
