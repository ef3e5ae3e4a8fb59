// newtop view end to end: the page's contract (self-contained, the CSV's rows as data, the body
// from the scenario) and bad input (one line, exit 2, no output file).

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "page.hpp"
#include "support/cli.hpp"

namespace test_view_cli {
namespace {

namespace fs = std::filesystem;
using newtop::test::CliResult;

CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

fs::path scratch(const std::string& name) {
  return newtop::test::scratch_path("newtop_view", name);
}

fs::path write_file(const std::string& name, const std::string& text) {
  return newtop::test::write_text(scratch(name), text);
}

std::string read_file(const fs::path& p) { return newtop::test::read_text(p); }

const char* kHeader = "t,p,q,r,gamma1,gamma2,gamma3,energy,area,geometric\n";

TEST(View, PageIsSelfContainedAndHoldsTheRows) {
  const fs::path csv = scratch("run.csv");
  const std::string scenario = newtop::test::example_path("heavy_top.toml");
  ASSERT_EQ(run("simulate " + scenario + " --t-end 1 --out " + csv.string()).code, 0);
  const fs::path html = scratch("run.html");
  const CliResult r =
      run("view " + csv.string() + " --scenario " + scenario + " -o " + html.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string page = read_file(html);
  // three.js is inside the page, and nothing is loaded from elsewhere.
  EXPECT_NE(page.find("REVISION"), std::string::npos);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("/*@"), std::string::npos) << "a placeholder was left in the page";
  // The data block holds the body of the scenario (A, B, C = 2, 2, 1).
  EXPECT_NE(page.find("\"inertia\":[2.0,2.0,1.0]"), std::string::npos);
  EXPECT_NE(page.find("\"attitude\":false"), std::string::npos);
}

TEST(View, BadInputIsOneLineExitTwoAndNoPage) {
  const std::string ok_row = "0,0.1,0.2,0.3,0,0,1,1,1,1\n";
  const struct {
    const char* name;
    std::string text;
    const char* expect;
  } cases[] = {
      {"json.csv", "{\"method\": \"splitting6\"}\n", "expected the header of a newtop trajectory"},
      {"columns.csv", "t,p,q,r,gamma1,gamma2\n0,0,0,0,0,1\n", "starting t,p,q,r,gamma1"},
      {"nan.csv", std::string(kHeader) + ok_row + "1,nan,0.2,0.3,0,0,1,1,1,1\n",
       "column p: expected a finite number, found 'nan'"},
      {"short.csv", std::string(kHeader) + "0,0.1,0.2\n", "expected 10 fields"},
      {"time.csv", std::string(kHeader) + ok_row + ok_row, "column t: expected a time greater"},
      {"zero.csv", std::string(kHeader) + "0,0.1,0.2,0.3,0,0,0,1,1,1\n", "non-zero vector"},
      {"quat.csv", "t,p,q,r,gamma1,gamma2,gamma3,q0,q1\n0,0,0,0,0,0,1,1,0\n",
       "expected all four columns q0,q1,q2,q3"},
      {"empty.csv", "", "found an empty file"},
      {"header.csv", kHeader, "expected at least one data row"},
  };
  for (const auto& c : cases) {
    const fs::path csv = write_file(c.name, c.text);
    const fs::path html = scratch(std::string(c.name) + ".html");
    const CliResult r = run("view " + csv.string() + " -o " + html.string());
    EXPECT_EQ(r.code, 2) << c.name;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(html)) << c.name;
  }
  const fs::path good = write_file("good.csv", std::string(kHeader) + ok_row);
  const CliResult frames = run("view " + good.string() + " --max-frames 1 -o x.html");
  EXPECT_EQ(frames.code, 2);
  EXPECT_NE(frames.err.find("--max-frames: expected an integer from 2 to"), std::string::npos)
      << frames.err;
  const CliResult scen = run("view " + good.string() + " --scenario " +
                             write_file("bad.toml", "[body]\ninertia = [1, 1]\n").string() +
                             " -o " + scratch("s.html").string());
  EXPECT_EQ(scen.code, 2);
  EXPECT_FALSE(fs::exists(scratch("s.html")));
}

TEST(View, OrbitRunWithItsScenarioAndMismatchesRefused) {
  const std::string orbit = newtop::test::example_path("satellite_700km.toml");
  const std::string fixed = newtop::test::example_path("heavy_top.toml");
  const fs::path ocsv = scratch("orbit.csv"), fcsv = scratch("fixed.csv");
  ASSERT_EQ(run("simulate " + orbit + " --t-end 100 --euler 321 --out " + ocsv.string()).code, 0);
  ASSERT_EQ(run("simulate " + fixed + " --t-end 1 --out " + fcsv.string()).code, 0);
  const fs::path html = scratch("orbit.html");
  const CliResult r =
      run("view " + ocsv.string() + " --scenario " + orbit + " -o " + html.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string page = read_file(html);
  EXPECT_NE(page.find("\"orbit\":true"), std::string::npos);
  EXPECT_NE(page.find("\"inertia\":[1200.0,1500.0,900.0]"), std::string::npos);
  // The LVLH attitude is not an inertial one: the page does not turn the body by it.
  EXPECT_NE(page.find("\"attitude\":false"), std::string::npos);
  const struct {
    fs::path csv;
    std::string scenario;
    const char* expect;
  } bad[] = {{ocsv, fixed, "expected the orbit scenario ([orbit])"},
             {fcsv, orbit, "found an orbit scenario ([orbit])"}};
  for (const auto& b : bad) {
    const fs::path out = scratch("mismatch.html");
    const CliResult m =
        run("view " + b.csv.string() + " --scenario " + b.scenario + " -o " + out.string());
    EXPECT_EQ(m.code, 2);
    EXPECT_NE(m.err.find(b.expect), std::string::npos) << m.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(View, FrameRowsAreEvenlySpacedWithBothEnds) {
  using newtop::viewer::frame_rows;
  EXPECT_EQ(frame_rows(3, 5), (std::vector<std::size_t>{0, 1, 2}));
  const auto r = frame_rows(1001, 11);
  ASSERT_EQ(r.size(), 11u);
  for (std::size_t k = 0; k < r.size(); ++k) EXPECT_EQ(r[k], 100 * k);
  const auto s = frame_rows(10, 4);  // 0, 3, 6, 9
  EXPECT_EQ(s, (std::vector<std::size_t>{0, 3, 6, 9}));
}

TEST(View, ParsedColumnsKeepTheNumbersExactly) {
  const auto tr = newtop::viewer::parse_trajectory(
      "t,p,q,r,gamma1,gamma2,gamma3,q0,q1,q2,q3\n0,0.1,0.2,0.30000000000000004,0.6,0,0.8,1,0,0,0\n",
      "mem.csv");
  ASSERT_TRUE(tr.has_attitude());
  EXPECT_EQ((*tr.column("r"))[0], 0.30000000000000004);
  EXPECT_EQ((*tr.column("gamma3"))[0], 0.8);
}

}  // namespace
}  // namespace test_view_cli
