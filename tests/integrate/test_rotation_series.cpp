// The rotation sub-flows' sin θ and cos θ − 1 (series for small angles, library beyond) against
// long double references: they must be round-off accurate in every branch, or the "exact" flows
// are not exact.

#include <gtest/gtest.h>

#include <cmath>

#include "newtop/integrate/sub_flows.hpp"

namespace newtop {
namespace test_rotation_series {
namespace {

// Each result is a short sum of terms each rounded once: 2 ulps (4.4e-16 relative) covers it.
constexpr double kUlps2 = 2 * 2.220446049250313e-16;

TEST(RotationSeries, RoundOffAccurateInEveryBranch) {
  for (double range : {1e-6, 1e-2, 0.1, 1.0, 3.0}) {  // short series, long series, library
    double max_s = 0, max_c = 0;
    for (int i = -2000; i <= 2000; ++i) {
      if (i == 0) continue;
      const double theta = range * i / 2000.0;
      double s, cm1;
      sin_cosm1(theta, s, cm1);
      const long double t = theta, half = std::sin(t / 2);
      const long double ref_s = std::sin(t), ref_c = -2 * half * half;
      max_s = std::max(max_s, double(std::fabs((s - ref_s) / ref_s)));
      max_c = std::max(max_c, double(std::fabs((cm1 - ref_c) / ref_c)));
    }
    EXPECT_LT(max_s, kUlps2) << "range " << range;
    EXPECT_LT(max_c, kUlps2) << "range " << range;
  }
}

}  // namespace
}  // namespace test_rotation_series
}  // namespace newtop
