// The step rule's own logarithm and power of two (taylor_step_log2, taylor_step_exp2): their error
// against the C library's log2l and exp2l (long double: 64-bit significands on x86-64, so the
// reference's own error is below 1/1000 of an ulp of a double) over the whole range the step rule
// can meet, exact powers of two, the special values, and the step of a series against the
// definition written with std::pow.

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

#include "newtop/integrate/taylor.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_taylor_math {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The error of `value` in units in the last place of the double nearest `ref` (for a subnormal
// result, the spacing of the subnormals). A reference computed in double (where long double is
// double) adds at most one ulp: the bounds are then widened by one.
double ulps(double value, long double ref) {
  const double r = static_cast<double>(ref);
  const double spacing = std::max(std::nextafter(std::abs(r), kInf) - std::abs(r),
                                  std::numeric_limits<double>::denorm_min());
  return static_cast<double>(std::abs(static_cast<long double>(value) - ref)) / spacing;
}

constexpr double kReferenceUlps = LDBL_MANT_DIG > DBL_MANT_DIG ? 0.0 : 1.0;

// log2 over every binade of the doubles (normal and subnormal), the neighbourhoods of 1 (where the
// result is small) and of √2 (the reduction's switch).
TEST(TaylorStepMath, Log2WithinItsBoundOverTheRange) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1074.0, 1024.0), frac(1.0, 2.0);
  double worst = 0.0;
  auto check = [&](double x) {
    worst =
        std::max(worst, ulps(detail::taylor_step_log2(x), std::log2(static_cast<long double>(x))));
  };
  for (int i = 0; i < 200000; ++i)
    check(std::ldexp(frac(rng), static_cast<int>(std::floor(u(rng)))));
  for (int k = 1; k < 2000; ++k) {
    check(1.0 + k * DBL_EPSILON);
    check(1.0 - k * DBL_EPSILON / 2);
    check(1.0 + k * 1e-6);
    check(1.0 - k * 1e-6);
  }
  double x = M_SQRT2, y = M_SQRT2;
  for (int k = 0; k < 100; ++k, x = std::nextafter(x, 0.0), y = std::nextafter(y, 2.0)) {
    check(x);
    check(y);
    check(std::ldexp(x, -1074 + 1));
    check(std::ldexp(y, 1000));
  }
  EXPECT_LE(worst, detail::kTaylorStepLog2Ulps + kReferenceUlps);
  std::printf("log2: largest error %.2f ulp\n", worst);
}

// 2^y over the normal results, the subnormal ones, and near 0 and the integers (the reduction).
TEST(TaylorStepMath, Exp2WithinItsBoundOverTheRange) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1074.0, 1024.0), small(-1.0, 1.0);
  double worst = 0.0;
  auto check = [&](double y) {
    worst =
        std::max(worst, ulps(detail::taylor_step_exp2(y), std::exp2(static_cast<long double>(y))));
  };
  for (int i = 0; i < 200000; ++i) check(u(rng));
  for (int i = 0; i < 20000; ++i) {
    check(small(rng));
    check(1e-10 * small(rng));
    const double k = std::floor(u(rng));
    check(k + 0.5 * small(rng));
    check(k + 0.5);
    check(k - 0.5);
  }
  EXPECT_LE(worst, detail::kTaylorStepExp2Ulps + kReferenceUlps);
  std::printf("exp2: largest error %.2f ulp\n", worst);
}

TEST(TaylorStepMath, PowersOfTwoAreExact) {
  for (int k = -1074; k <= 1023; ++k) {
    const double x = std::ldexp(1.0, k);
    EXPECT_EQ(detail::taylor_step_log2(x), static_cast<double>(k)) << k;
    EXPECT_EQ(detail::taylor_step_exp2(static_cast<double>(k)), x) << k;
  }
  EXPECT_EQ(detail::taylor_step_log2(1.0), 0.0);
  EXPECT_EQ(detail::taylor_step_exp2(0.0), 1.0);
}

TEST(TaylorStepMath, SpecialValues) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(detail::taylor_step_log2(0.0), -kInf);
  EXPECT_EQ(detail::taylor_step_log2(-0.0), -kInf);
  EXPECT_EQ(detail::taylor_step_log2(kInf), kInf);
  EXPECT_TRUE(std::isnan(detail::taylor_step_log2(-1.0)));
  EXPECT_TRUE(std::isnan(detail::taylor_step_log2(-kInf)));
  EXPECT_TRUE(std::isnan(detail::taylor_step_log2(nan)));
  EXPECT_EQ(detail::taylor_step_log2(DBL_MAX), std::log2(DBL_MAX));
  EXPECT_EQ(detail::taylor_step_exp2(kInf), kInf);
  EXPECT_EQ(detail::taylor_step_exp2(1024.0), kInf);
  EXPECT_EQ(detail::taylor_step_exp2(5000.0), kInf);
  EXPECT_EQ(detail::taylor_step_exp2(-kInf), 0.0);
  EXPECT_EQ(detail::taylor_step_exp2(-1076.0), 0.0);
  EXPECT_EQ(detail::taylor_step_exp2(-5000.0), 0.0);
  EXPECT_TRUE(std::isnan(detail::taylor_step_exp2(nan)));
}

// The step of a series against min over n = p − 1, p of (ε/c_n)^(1/n) exp(−0.7/(p − 1)) with the
// C library's pow and exp: the logarithms (|log2| ≲ 100 here) within 4 ulp give log2 h within
// ~1e-13, so h within kStepRelative = 1e-12 relative.
constexpr double kStepRelative = 1e-12;

TEST(TaylorStepMath, StepIsTheDefinition) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const State x = test::generic_state(m);
  for (int p : {8, 12, 17, 25, 30}) {
    detail::TaylorSeries s;
    detail::taylor_expand(detail::TaylorModel(m), x, nullptr, p, s);
    auto norm = [&](int n) {
      double r = 0.0;
      for (int c = 0; c < 3; ++c) {
        r = std::max({r, std::abs(s.m[static_cast<std::size_t>(n)][static_cast<std::size_t>(c)]),
                      std::abs(s.gamma[static_cast<std::size_t>(n)][static_cast<std::size_t>(c)])});
      }
      return r;
    };
    for (double tol : {1e-6, 1e-9, 1e-12, 1e-15}) {
      const double eps = std::max(tol, tol * norm(0));
      const double h =
          std::min(std::pow(eps / norm(p), 1.0 / p), std::pow(eps / norm(p - 1), 1.0 / (p - 1))) *
          std::exp(-0.7 / (p - 1));
      EXPECT_NEAR(detail::taylor_step(s, tol, tol), h, kStepRelative * h) << p << " " << tol;
    }
  }
}

}  // namespace
}  // namespace test_taylor_math
}  // namespace newtop
