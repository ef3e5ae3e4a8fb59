// Every integer option of every subcommand, found in `newtop SUB --help` (CLI11 types them INT):
// the largest integers and beyond, negative values, the ends of the option's range moved out by
// one and non-integers are each refused at parsing in one line that names the option, the range
// expected and the value found (exit 2).

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace test_input_ranges_cli {
namespace {

using newtop::test::CliResult;

CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::vector<std::string> subcommands() {
  const CliResult r = run("--help");
  std::vector<std::string> subs;
  bool in_list = false;
  for (const std::string& l : lines(r.out)) {
    if (l.rfind("Subcommands:", 0) == 0) {
      in_list = true;
    } else if (in_list && l.size() > 2 && l[0] == ' ' && l[2] != ' ') {
      subs.push_back(l.substr(2, l.find(' ', 2) - 2));
    }
  }
  return subs;
}

// The integer options of a subcommand: "--name INT" in its help.
std::vector<std::string> integer_options(const std::string& sub) {
  const CliResult r = run(sub + " --help");
  const std::regex option(R"(^\s+(?:-\w,)?(--[\w-]+) INT\b)");
  std::vector<std::string> out;
  for (const std::string& l : lines(r.out)) {
    std::smatch m;
    if (std::regex_search(l, m, option)) out.push_back(m[1]);
  }
  return out;
}

// Positionals and required options that let parsing reach the option (nothing is read: the
// refusal comes first).
std::string rest(const std::string& sub) {
  if (sub == "view") return " trajectory.csv -o page.html";
  if (sub == "section") return " scenario.toml --surface 'gamma3 = 0'";
  if (sub == "sweep") return " sweep.toml";
  if (sub == "continue") return " scenario.toml --family periodic --parameter energy --range 1:2";
  return " scenario.toml";
}

// Refused in one line on stderr naming the option, what was expected and the value; nothing on
// stdout.
void expect_refused(const std::string& sub, const std::string& option, const std::string& value) {
  const CliResult r = run(sub + rest(sub) + " " + option + " " + value);
  const std::string what = "newtop " + sub + " " + option + " " + value;
  EXPECT_EQ(r.code, 2) << what << "\n" << r.err;
  EXPECT_EQ(lines(r.err).size(), 1u) << what << "\n" << r.err;
  EXPECT_NE(r.err.find(option + ": expected "), std::string::npos) << what << "\n" << r.err;
  EXPECT_NE(r.err.find(value), std::string::npos) << what << "\n" << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << what;
  EXPECT_TRUE(r.out.empty()) << what << "\n" << r.out;
}

TEST(InputRanges, EveryIntegerOptionIsRangeChecked) {
  const std::vector<std::string> subs = subcommands();
  ASSERT_GE(subs.size(), 10u);
  int checked = 0;
  for (const std::string& sub : subs) {
    for (const std::string& option : integer_options(sub)) {
      ++checked;
      // Beyond every range (no option takes a negative or zero count) and not integers at all.
      for (const char* v : {"9223372036854775808", "-9223372036854775809", "99999999999999999999",
                            "-1", "0", "1e9", "1.5", "0x10"}) {
        expect_refused(sub, option, v);
      }
      // The range the message names: its ends moved out by one are refused, and so are the
      // largest 32- and 64-bit integers where they lie beyond it.
      const CliResult r = run(sub + rest(sub) + " " + option + " -1");
      std::smatch m;
      if (std::regex_search(r.err, m, std::regex(R"(from (-?\d+) to (-?\d+))"))) {
        const long long lo = std::stoll(m[1]), hi = std::stoll(m[2]);
        expect_refused(sub, option, std::to_string(lo - 1));
        expect_refused(sub, option, std::to_string(hi + 1));
        for (const long long big : {2147483647LL, 2147483648LL, 9223372036854775807LL}) {
          if (big > hi) expect_refused(sub, option, std::to_string(big));
        }
      } else {  // a set of values (simulate --euler): the large ones are refused too
        for (const char* v : {"2147483648", "9223372036854775807"}) expect_refused(sub, option, v);
      }
    }
  }
  // analytic, find-integrals (--degree, --points), libration, rotations, section (--crossings,
  // --orbits), simulate (--every, --euler), stability, sweep, view: an option that lost its INT
  // type (or its range) would drop out of this count.
  EXPECT_GE(checked, 12);
}

// A value inside the range passes the check (it reaches the command, which reads its file).
TEST(InputRanges, ValuesInTheRangeReachTheCommand) {
  const CliResult r = run("section missing.toml --surface 'gamma3 = 0' --orbits 12");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.find("--orbits"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("missing.toml"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace test_input_ranges_cli
