// The potential file of `newtop find-integrals --potential` (newtop/io/potential_file.hpp): total
// on any bytes, every number exact and in range, the same one-line message from the library and
// the program; a potential it accepts gives a finite search.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "newtop/io/potential_file.hpp"
#include "reject.hpp"
#include "support/cli.hpp"

namespace newtop::io {
namespace test_potential_file {
namespace {

using newtop::test::run_newtop;
using newtop::test::Stderr;

const std::string kScenario = newtop::test::example_path("analytic_free_body.toml");  // I = 1, 2, 3

Body free_body() { return Body::from_principal({1.0, 2.0, 3.0}, 1.0, Vec3::Zero()); }

// "s.toml" + tail from the library, FILE + tail from the program (exit code 2, one line).
void expect_refused(const std::string& name, const std::string& bytes, const std::string& tail) {
  try {
    parse_potential(bytes, "s.toml", free_body());
    ADD_FAILURE() << name << ": accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "s.toml" + tail) << name;
  }
  const std::string path = test::write_file(name + ".toml", bytes);
  const auto r =
      run_newtop("find-integrals " + kScenario + " --potential " + path, Stderr::separate);
  EXPECT_EQ(r.code, 2) << name;
  EXPECT_EQ(r.err, "newtop: error: " + path + tail + "\n") << name;
  EXPECT_EQ(r.out, "") << name;
}

TEST(PotentialFile, ReadsTermsExactly) {
  const PolynomialPotential v = parse_potential(
      "# V = γ3 − ½ γ1γ2γ3\n[potential]\nterms = [[1, 0, 0, 1], [-0.5, 1, 1, 1], "
      "[4611686018427387904, 0, 8, 0]]\n",
      "s.toml", free_body());
  ASSERT_EQ(v.terms.size(), 3u);
  EXPECT_EQ(v.terms[1].coefficient, -0.5);
  EXPECT_EQ(v.terms[1].power, (std::array<int, 3>{1, 1, 1}));
  EXPECT_EQ(v.terms[2].coefficient, 0x1p62);  // an integer a double holds exactly
  EXPECT_TRUE(parse_potential("[potential]\nterms = []\n", "s.toml", free_body()).terms.empty());
}

TEST(PotentialFile, CoefficientsInRange) {
  // 1e308 gave null coefficients from the search: the squares overflowed.
  expect_refused("p_1e308", "[potential]\nterms = [[1e308, 2, 0, 0]]\n",
                 ":2:10: [potential] terms[0]: expected a coefficient of magnitude at most "
                 "1e+100, found 1e+308");
  expect_refused("p_sum", "[potential]\nterms = [[1e99, 2, 0, 0], [1e99, 0, 2, 0]]\n",
                 ":2:9: [potential] terms: expected sum |coefficient| * 8 / min(A, B, C) of at "
                 "most 1e+100, found 2e+99 * 8 / 1 = 1.6e+100");
  expect_refused("p_int", "[potential]\nterms = [[9007199254740993, 2, 0, 0]]\n",
                 ":2:11: [potential] terms[0]: coefficient: expected a number that a double holds "
                 "exactly, found the integer 9007199254740993 (the nearest double is "
                 "9007199254740992.0; write it with a decimal point to accept the rounding)");
  expect_refused("p_nan", "[potential]\nterms = [[nan, 2, 0, 0]]\n",
                 ":2:11: [potential] terms[0]: coefficient: expected a finite number, found nan");
  // At the bound the search is finite: no null among its numbers.
  const std::string path = test::write_file(
      "p_at_bound.toml",
      "[potential]\nterms = [[1e98, 2, 0, 0], [-1e98, 0, 1, 1], [2.4e98, 0, 0, 8]]\n");
  const auto r = run_newtop("find-integrals " + kScenario + " --potential " + path + " --json",
                            Stderr::separate);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& x : j["singular_values"]) EXPECT_TRUE(x.is_number()) << x;
  for (const auto& i : j["integrals"]) {
    for (const auto& [k, c] : i["coefficients"].items()) EXPECT_TRUE(c.is_number()) << k;
  }
}

TEST(PotentialFile, ExponentsAndRows) {
  expect_refused("p_float_exponent", "[potential]\nterms = [[1.0, 2.0, 0, 0]]\n",
                 ":2:10: [potential] terms[0]: expected the exponent of gamma1 to be an integer in "
                 "[0, 8], found the float 2.0");
  expect_refused("p_exponent_9", "[potential]\nterms = [[1.0, 0, 0, 9]]\n",
                 ":2:10: [potential] terms[0]: expected the exponent of gamma3 to be an integer in "
                 "[0, 8], found the integer 9");
  expect_refused("p_duplicate", "[potential]\nterms = [[1.0, 2, 0, 0], [2.0, 2, 0, 0]]\n",
                 ":2:26: [potential] terms[1]: the exponents (2, 0, 0) repeat terms[0]: give each "
                 "monomial once");
  expect_refused(
      "p_short_row", "[potential]\nterms = [[0.25, 2, 0]]\n",
      ":2:10: [potential] terms[0]: expected [coefficient, i, j, k], found an array of 3");
  expect_refused("p_not_array", "[potential]\nterms = 3\n",
                 ":2:9: [potential] terms: expected an array of [coefficient, i, j, k], found the "
                 "integer 3");
}

TEST(PotentialFile, KeysAndSections) {
  expect_refused("p_typo", "[potential]\nterm = [[0.25, 2, 0, 0]]\n",
                 ":2:1: unknown key 'term' in [potential] — did you mean 'terms'?");
  expect_refused("p_section", "[potentail]\nterms = [[0.25, 2, 0, 0]]\n",
                 ":1:2: unknown section [potentail] — did you mean [potential]?");
  expect_refused("p_missing", "# nothing\n", ":1:1: potential: missing section [potential]");
  expect_refused("p_no_terms", "[potential]\n",
                 ":1:1: [potential] terms: missing: give terms = [[coefficient, i, j, k], ...]");
}

TEST(PotentialFile, HostileTomlAndFiles) {
  expect_refused("p_nonascii", "[potential]\nterms = [[1, 2, 0, 0]]\u00a1\n",
                 ":2:23: malformed TOML: the character U+00A1 outside a string or comment");
  std::string deep = "potential";
  for (int i = 0; i < 20000; ++i) deep += ".a";
  expect_refused("p_dotted", deep + " = 1\n",
                 ":1:24: malformed TOML: a dotted key of more than 8 parts");
  const auto r =
      run_newtop("find-integrals " + kScenario + " --potential /dev/zero", Stderr::separate);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err,
            "newtop: error: /dev/zero: potential file: expected a regular file, found a "
            "character device\n");
}

}  // namespace
}  // namespace test_potential_file
}  // namespace newtop::io
