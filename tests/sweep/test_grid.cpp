// Grid points (newtop/core/grid.hpp) and the axes of a sweep file: the decimal points a user writes
// come out as those decimals (0.9, not 0.8999999999999999, on a grid from 0 to 3 in steps of 0.1).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "newtop/core/grid.hpp"
#include "newtop/core/types.hpp"
#include "newtop/sweep/sweep.hpp"
#include "support/cli.hpp"

namespace test_grid {
namespace {

using newtop::grid_value;

/// The double a reader makes of the decimal text: the value the user means by it.
double decimal(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

TEST(Grid, TenthsFromZeroToThreeAreTheDecimals) {
  // 0.1 k for k = 0..30: the old start + (k/30)(stop − start) gave 0.8999999999999999 at k = 9.
  for (int k = 0; k <= 30; ++k) {
    const std::string text = std::to_string(k / 10) + "." + std::to_string(k % 10);
    EXPECT_EQ(grid_value(0.0, 3.0, 31, k), decimal(text)) << text;
    EXPECT_EQ(newtop::format_number(grid_value(0.0, 3.0, 31, k)),
              newtop::format_number(decimal(text)));
  }
  EXPECT_EQ(newtop::format_number(grid_value(0.0, 3.0, 31, 9)), "0.9");
}

TEST(Grid, DecimalEndsAndNegativeGrids) {
  // From −1.5 to 2.5 in steps of 0.05 (81 points), and from 0.1 to 0.9 in steps of 0.01.
  for (int k = 0; k <= 80; ++k) {
    EXPECT_EQ(grid_value(-1.5, 2.5, 81, k), decimal(fixed(-1.5 + 0.05 * k, 2))) << k;
  }
  for (int k = 0; k <= 80; ++k) {
    EXPECT_EQ(grid_value(0.1, 0.9, 81, k), decimal(fixed(0.1 + 0.01 * k, 2))) << k;
  }
  EXPECT_EQ(std::signbit(grid_value(-1.0, 1.0, 3, 1)), false);  // 0, never −0
}

TEST(Grid, EndsAreExactAndOtherGridsAreWithinAnUlp) {
  // Ends that are no short decimals (1/3, π): the floating-point formula, whose error is a few
  // roundings of values no larger than max(|lo|, |hi|): 4 ulp of that bound.
  const double lo = 1.0 / 3.0, hi = std::numbers::pi;
  const int n = 7;
  EXPECT_EQ(grid_value(lo, hi, n, 0), lo);
  EXPECT_EQ(grid_value(lo, hi, n, n - 1), hi);
  for (int k = 0; k < n; ++k) {
    const long double exact = lo + static_cast<long double>(k) * (hi - lo) / (n - 1);
    const double bound = 4 * std::nextafter(hi, 10.0) - 4 * hi;
    EXPECT_LE(std::fabs(static_cast<double>(exact - grid_value(lo, hi, n, k))), bound) << k;
  }
  EXPECT_EQ(grid_value(2.5, 7.0, 1, 0), 2.5);
}

TEST(Grid, SweepAxisFromStartStopCountIsTheDecimalGrid) {
  const std::string path =
      newtop::test::write_text(newtop::test::scratch_path("newtop_grid", "tenths.toml"),
                               "scenario = \"" + newtop::test::example_path("heavy_top.toml") +
                                   "\"\nquantities = [\"drift\"]\n[[axes]]\nkey = "
                                   "\"initial.omega[2]\"\nstart = 0\nstop = 3\ncount = 31\n")
          .string();
  const newtop::sweep::SweepFile s = newtop::sweep::load_sweep(path);
  ASSERT_EQ(s.axes.size(), 1u);
  ASSERT_EQ(s.axes[0].values.size(), 31u);
  EXPECT_EQ(newtop::format_number(s.axes[0].values[9]), "0.9");
  for (int k = 0; k <= 30; ++k) {
    EXPECT_EQ(s.axes[0].values[static_cast<std::size_t>(k)],
              decimal(std::to_string(k / 10) + "." + std::to_string(k % 10)));
  }
}

}  // namespace
}  // namespace test_grid
