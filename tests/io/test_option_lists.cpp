// The one reader of the command line's colon-separated values (io::read_colon_values) and the
// range options on top of it: LO:HI:N, A:B and P:Q read whole or refused.

#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "newtop/io/option_lists.hpp"

namespace newtop::io {
namespace test_option_lists {
namespace {

TEST(ReadColonValues, ReadsLoHiNWhole) {
  const auto v = read_colon_values<double, double, int>("-0.5:2.25:7");
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, std::make_tuple(-0.5, 2.25, 7));
  EXPECT_TRUE((read_colon_values<double, double, int>(" 1 : 2 : 3 ").has_value()));
}

TEST(ReadColonValues, RefusesAnythingButTheValuesAsked) {
  for (const std::string bad :
       {"1:2", "1:2:3:4", "1:2:3x", "1:2:3.5", "1;2;3", "a:b:c", "", "1::3", ":1:2:3"}) {
    EXPECT_FALSE((read_colon_values<double, double, int>(bad).has_value())) << bad;
  }
  EXPECT_FALSE((read_colon_values<int, int>("3:2.5").has_value()));
  EXPECT_FALSE((read_colon_values<double, double>("1:2:3").has_value()));
  const auto pq = read_colon_values<int, int>("3:2");
  ASSERT_TRUE(pq.has_value());
  EXPECT_EQ(*pq, std::make_tuple(3, 2));
}

TEST(RangeOptions, EachOptionChecksItsOwnBoundsOnTheSharedReader) {
  const Range r = parse_range("--scan-omega", "0:3:4", false);
  EXPECT_EQ(r.values(), (std::vector<double>{0.0, 1.0, 2.0, 3.0}));
  EXPECT_THROW(parse_range("--scan-omega", "0:3:0", false), InputError);
  EXPECT_THROW(parse_radius_scan("2:10:1"), InputError);  // at least two distances
  EXPECT_EQ(parse_radius_scan("2:10:5").n, 5);
  EXPECT_THROW(parse_spin("2:1:3"), InputError);                              // LO > HI
  EXPECT_THROW(parse_ratio_scan("k_R=-0.5:0.5:3,k_Y=-1:0.5:3"), InputError);  // |k| < 1
  EXPECT_EQ(parse_resonances("1:1,3:2").size(), 2u);
  EXPECT_THROW(parse_resonances("1:1,3"), InputError);
}

}  // namespace
}  // namespace test_option_lists
}  // namespace newtop::io
