// Hostile scenario files (issue: every reader total): TOML that would overflow toml++'s stack or
// reach its undefined behaviour, integers a double cannot hold, numbers whose derived quantities
// overflow, and files that are not regular files. Each is checked with its exact bytes: one line,
// exit code 2, the same message from the library and the program.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "newtop/io/scenario.hpp"
#include "reject.hpp"

namespace newtop::io {
namespace test_scenario_hostile {
namespace {

using test::expect_rejected;

const std::string kInitial = "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n";
const std::string kBody =
    "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\ncenter_of_mass = [0.1, 0.0, 0.3]\n";
const std::string kHeavyTop =
    "[body]\ninertia = [2.0, 2.0, 1.0]\nmass = 1.0\ncenter_of_mass = [0.0, 0.0, 0.5]\n";

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

TEST(ScenarioHostile, DeepDottedKeyAndNestingAreBoundedBeforeParsing) {
  // 50,000 levels overflowed the stack inside toml++.
  expect_rejected("dotted_50000", "a" + repeat(".a", 49999) + " = 1\n",
                  ":1:16: malformed TOML: a dotted key of more than 8 parts");
  expect_rejected("arrays_2000", "a = " + repeat("[", 2000) + "\n",
                  ":1:21: malformed TOML: arrays and inline tables nested more than 16 deep");
  expect_rejected("inline_tables_2000", "a = " + repeat("{b = ", 2000) + "\n",
                  ":1:85: malformed TOML: arrays and inline tables nested more than 16 deep");
  // Within the bounds the parser runs: 8 parts reach the key check.
  expect_rejected("dotted_8", "a.b.c.d.e.f.g.h = 1\n" + kBody,
                  ":1:1: unknown section [a] (expected [body], [mass_model], [field], [initial], "
                  "[integrate], [output])");
}

TEST(ScenarioHostile, NonAsciiWhereTomlxxAsksForWhitespace) {
  // Each of these reached __builtin_unreachable in toml++ 3.3 (is_non_ascii_horizontal_whitespace).
  expect_rejected("u00a1_after_value", "a = 1\u00a1\n",
                  ":1:6: malformed TOML: the character U+00A1 in a value (numbers, booleans and "
                  "dates are ASCII)");
  expect_rejected("u3001_after_value", "a = 1 \u3001\n",
                  ":1:7: malformed TOML: the character U+3001 outside a string or comment");
  expect_rejected("ufeff_inside", "a = 1\n\ufeff",
                  ":2:1: malformed TOML: the character U+FEFF outside a string or comment");
  expect_rejected("bare_key", "\u00e9 = 1\n",
                  ":1:1: malformed TOML: the character U+00E9 outside a string or comment");
  expect_rejected("escaped", "a = \"\"\"\\\u00e9\"\"\"\n",
                  ":1:9: malformed TOML: the character U+00E9 after a backslash (not an escape "
                  "sequence)");
  expect_rejected("line_ending", "a = \"\"\"x \\\n  \u00e9\"\"\"\n",
                  ":2:3: malformed TOML: the character U+00E9 right after a line-ending backslash "
                  "(not read there: toml++ 3.3 mishandles it)");
  expect_rejected("after_closing_quotes", "a = \"\"\"x\"\"\"\"\u00e9\"\n",
                  ":1:13: malformed TOML: the character U+00E9 outside a string or comment");
  expect_rejected("invalid_utf8", "a = 1 \xff\n",
                  ":1:7: malformed TOML: the byte 0xFF (not UTF-8) outside a string or comment");
  // Non-ASCII where TOML allows it: comments, strings, a byte-order mark.
  const Scenario s = parse_scenario("\xEF\xBB\xBF# Poincaré — γ\n" + kBody +
                                        "[field]\nkind = \"uniform\"\ng = 9.81 # é\n" + kInitial +
                                        "[output]\nfile = \"trajectoire_été.csv\"\n",
                                    "s.toml");
  EXPECT_EQ(*s.output.file, "trajectoire_été.csv");
}

// toml++ 3.3 reads a value that starts with neither a quote nor a bracket as one token up to a
// blank, a line break, `,`, `]`, `}` or `#`; quotes inside it do not start a string, and each of
// its characters goes through the whitespace table that is undefined for some non-ASCII characters.
// The bounds took such a quote for the start of a string and let the string's bytes through.
TEST(ScenarioHostile, NonAsciiInsideABareValueAfterAQuote) {
  const std::string what =
      ": malformed TOML: the character U+00E9 in a value (numbers, booleans "
      "and dates are ASCII)";
  expect_rejected("glued_quote", "mass = 0PPP'\u00e9'\n", ":1:13" + what);
  expect_rejected("quote_after_control", "a = 0.2\x12\"\u00e9\"\n", ":1:10" + what);
  expect_rejected("quotes_in_token", "a = 0\"\"*x\"\"\"\"\u00e9\"\n", ":1:14" + what);
  expect_rejected("equals_in_token", "6=3===\"\u00e9\"\n", ":1:8" + what);
  expect_rejected("array_element", "a = [1, 2'\u00e9']\n", ":1:11" + what);
  expect_rejected("inline_table", "a = {b = 2'\u00e9'}\n", ":1:12" + what);
  // Quoted strings keep their non-ASCII characters as values, in arrays and inline tables, and
  // as quoted keys: the file reaches the scenario's own checks.
  expect_rejected(
      "quoted_values",
      "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\n\"\u00e9\" = [\"\u00e9\", "
      "'\u00fc', {b = \"\u00f6\"}]\n",
      ":4:1: unknown key '\u00e9' in [body] (expected one of inertia, inertia_tensor, mass, "
      "center_of_mass, gyrostat)");
}

TEST(ScenarioHostile, IntegersReadExactlyOrRefused) {
  const std::string tail =
      "expected a number that a double holds exactly, found the integer 9007199254740993 (the "
      "nearest double is 9007199254740992.0; write it with a decimal point to accept the "
      "rounding)";
  expect_rejected("mass_2p53_plus_1",
                  "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 9007199254740993\n[field]\ng = 1\n"
                  "lambda = 1\n" +
                      kInitial,
                  ":3:8: [body] mass: " + tail);
  expect_rejected("vector_2p53_plus_1",
                  "[body]\ninertia = [1, 9007199254740993, 9007199254740992]\n[field]\ng = 1\n"
                  "lambda = 1\n" +
                      kInitial,
                  ":2:15: [body] inertia: element 2: " + tail);
  expect_rejected("points_2p53_plus_1",
                  "[mass_model]\npoints = [[1, 1, 0, 0], [9007199254740993, -1, 0, 0]]\n"
                  "[field]\nmu = 1\nR = 10\n" +
                      kInitial,
                  ":2:26: [mass_model] points: row 2, column 1: " + tail);
  // Exactly representable integers are read as they are: 2^53 and 2^62.
  const Scenario s = parse_scenario(
      "[body]\ninertia = [1, 1.5, 2.2]\nmass = 4611686018427387904\n"
      "[field]\ng = 1\nlambda = 1\n" +
          kInitial + "[integrate]\nmax_steps = 9007199254740992\n",
      "s.toml");
  EXPECT_EQ(s.model.body().mass(), 0x1p62);
  EXPECT_EQ(*s.integrate.max_steps, std::int64_t{1} << 53);
  // Integer keys: integers only, in range.
  const std::string field = kBody + "[field]\ng = 1\nlambda = 1\n" + kInitial;
  expect_rejected("every_float", field + "[output]\nevery = 3.0\n",
                  ":12:9: [output] every: expected an integer in [1, 9223372036854775807], "
                  "found the float 3.0");
  expect_rejected("max_steps_zero", field + "[integrate]\nmax_steps = 0\n",
                  ":12:13: [integrate] max_steps: expected an integer in [1, "
                  "9223372036854775807], found the integer 0");
  expect_rejected("max_steps_2p64", field + "[integrate]\nmax_steps = 18446744073709551616\n",
                  ":12:33: malformed TOML: Error while parsing decimal integer: "
                  "'18446744073709551616' is not representable in 64 bits");
}

TEST(ScenarioHostile, OverflowNamesTheKey) {
  const std::string bound = " exceeds 1e+300, the bound on every derived quantity (";
  expect_rejected("mass_1e300",
                  "[body]\ninertia = [2.0, 2.0, 1.0]\nmass = 1e300\ncenter_of_mass = [0, 0, 0.5]\n"
                  "[field]\nkind = \"uniform\"\ng = 9.81\n" +
                      kInitial,
                  ":3:8: [body] mass: M g |r0| (the potential's linear term) = "
                  "4.9050000000000005e+300" +
                      bound + "M = 1e+300, g = 9.81, |r0| = 0.5)");
  expect_rejected(
      "g_1e300", kHeavyTop + "[field]\nkind = \"uniform\"\ng = 1e300\n" + kInitial,
      ":7:5: [field] g: the bound |m||omega| + |L| over the motion = 3.32842712474619e+300" +
          bound + "kinetic energy <= 1e+300, |omega| <= 1.4142135623730951e+150, |m| <= 2e+150)");
  expect_rejected("lambda_1e300", kBody + "[field]\ng = 1\nlambda = 1e300\n" + kInitial,
                  ":7:10: [field] lambda: lambda max(I) (the potential's quadratic term) = "
                  "2.2000000000000004e+300" +
                      bound + "lambda = 1e+300, max I = 2.2)");
  expect_rejected("N_1e300", kBody + "[field]\nkind = \"brun\"\nN = 1e300\n" + kInitial,
                  ":7:5: [field] N: lambda max(I) (the potential's quadratic term) = "
                  "2.2000000000000004e+300" +
                      bound + "lambda = 1e+300, max I = 2.2)");
  expect_rejected("mu_1e300", kBody + "[field]\nmu = 1e300\nR = 1\n" + kInitial,
                  ":6:6: [field] mu: lambda max(I) (the potential's quadratic term) = "
                  "6.600000000000001e+300" +
                      bound + "lambda = 3e+300, max I = 2.2)");
  expect_rejected("mu_R_overflow", kBody + "[field]\nmu = 1e300\nR = 1e-10\n" + kInitial,
                  ":6:6: [field] mu: g = mu/R^2 overflows to inf (mu = 1e+300, R = 1e-10)");
  expect_rejected("mu_R_underflow", kBody + "[field]\nmu = 1e-300\nR = 1e10\n" + kInitial,
                  ":6:6: [field] mu: g = mu/R^2 underflows to 1e-320 (mu = 1e-300, R = 1e+10)");
  expect_rejected("omega_1e300",
                  kBody +
                      "[field]\ng = 1\nlambda = 1\n[initial]\nomega = [1e300, 0, 0]\n"
                      "gamma = [0, 0, 1]\n",
                  ":9:9: [initial] omega: the kinetic energy ½ ω·Iω = inf" + bound +
                      "|omega| = 1e+300, max I = 2.2)");
  expect_rejected(
      "r0_1e300",
      "[body]\ninertia = [1.0, 1.5, 2.2]\ncenter_of_mass = [1e300, 0, 0]\n[field]\n"
      "g = 1\nlambda = 1\n" +
          kInitial,
      ":3:18: [body] center_of_mass: the bound |m||omega| + |L| over the motion = "
      "6.932958789676532e+300" +
          bound + "kinetic energy <= 2e+300, |omega| <= 2e+150, |m| <= 2.9664793948382655e+150)");
  expect_rejected(
      "k_1e300",
      "[body]\ninertia = [1.0, 1.5, 2.2]\ngyrostat = [0, 0, 1e300]\n[field]\ng = 1\n"
      "lambda = 1\n" +
          kInitial,
      ":3:12: [body] gyrostat: the bound |m||omega| + |L| over the motion = "
      "2.5426364270182244e+300" +
          bound +
          "kinetic energy <= 3.2325000000000004, |omega| <= 2.5426364270182242, |m| <= 1e+300)");
  expect_rejected("point_mass_1e300",
                  "[mass_model]\npoints = [[1e300, 1, 0, 0], [1, -1, 0, 0], [2, 0, 1, 0], "
                  "[2, 0, -1, 0], [3, 0, 0, 1], [3, 0, 0, -1]]\n[field]\nmu = 1\nR = 10\n" +
                      kInitial,
                  ":2:10: [mass_model] points: the bound |m||omega| + |L| over the motion = inf" +
                      bound +
                      "kinetic energy <= 7.080000000000002e+299, |omega| <= "
                      "3.7629775444453565e+149, |m| <= inf)");
}

TEST(ScenarioHostile, NormalizeWithoutOverflowOrUnderflow) {
  const std::string head = kBody + "[field]\ng = 1\nlambda = 1\n[initial]\nomega = [0, 0, 0]\n";
  const Scenario big =
      parse_scenario(head + "gamma = [1e200, 1e200, 0]\nnormalize = true\n", "s.toml");
  // The same unit vector as [1, 1, 0] gives (the norm 1e200·√2 no longer overflows to inf).
  EXPECT_EQ(big.initial.gamma, Vec3(1.0, 1.0, 0.0).normalized());
  const Scenario tiny =
      parse_scenario(head + "gamma = [0, -5e-324, 0]\nnormalize = true\n", "s.toml");
  EXPECT_EQ(tiny.initial.gamma, Vec3(0.0, -1.0, 0.0));
  expect_rejected("gamma_zero", head + "gamma = [0, 0, 0]\nnormalize = true\n",
                  ":10:9: [initial] gamma: expected a unit vector, found [0, 0, 0]");
}

}  // namespace
}  // namespace test_scenario_hostile
}  // namespace newtop::io
