// The sub-flows of the splitting against independent references: the spin flow against Rodrigues'
// rotation in long double, the spin split of the free body against the exact Euler–Poinsot motion
// where it is exact (a symmetric body), the working frame of the split, and the coefficients of the
// near-integrable tables against the quadrature rules they are built on.

#include <gtest/gtest.h>

#include <cmath>

#include "newtop/integrate/free_body_flow.hpp"
#include "newtop/integrate/splitting.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_sub_flows {
namespace {

using test::kEps;

// A short sum of terms each rounded once, the series truncated below 3e-22: 2 ulps.
constexpr double kUlps2 = 2 * kEps;

TEST(SpinFactors, RoundOffAccurateInEveryBranch) {
  for (double range : {1e-6, 1e-2, 0.1, 1.0, 3.0}) {  // short series, long series, library
    double max1 = 0, max2 = 0;
    for (int i = 1; i <= 2000; ++i) {
      const double phi = range * i / 2000.0;
      double f1, f2;
      spin_factors(phi * phi, f1, f2);
      const long double p = phi, h = std::sin(p / 2);
      const long double ref1 = std::sin(p) / p, ref2 = 2 * h * h / (p * p);
      max1 = std::max(max1, double(std::fabs((f1 - ref1) / ref1)));
      max2 = std::max(max2, double(std::fabs((f2 - ref2) / ref2)));
    }
    EXPECT_LT(max1, kUlps2) << "range " << range;
    EXPECT_LT(max2, kUlps2) << "range " << range;
  }
}

// γ̇ = γ × m/I turns γ about m by −|m| t/I; Eigen's AngleAxis in long double is the reference.
// The flow rounds a few terms of size |γ|: 4 ε.
constexpr double kSpinAgreement = 4 * kEps;

TEST(SpinFlow, IsTheRotationAboutTheMomentum) {
  const Vec3 m(0.3, -1.2, 0.7), g = Vec3(0.48, -0.6, 0.64);
  for (double tau : {1e-4, 0.02, 0.3, 2.5}) {  // each branch of spin_factors
    Phase z;
    for (int i = 0; i < 3; ++i) z.set(i, m[i], g[i]);
    spin_flow(z, tau);
    using V = Eigen::Matrix<long double, 3, 1>;
    const V ml = m.cast<long double>();
    const V ref =
        Eigen::AngleAxis<long double>(-tau * ml.norm(), ml.normalized()) * g.cast<long double>();
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(z.g(i), double(ref[i]), kSpinAgreement) << "tau " << tau;
      EXPECT_EQ(z.m(i), m[i]);  // m is constant along the flow
    }
  }
}

// For a symmetric body A = B with the reference axis among the equal ones, the spin split has one
// zero rate, so its sub-flows commute and T(h) is the exact free-body flow: one step of any size
// agrees with Euler–Poinsot (itself exact to ~1e-14, tests/integrable) to round-off of the ~10
// elementary operations per sub-flow and of the elliptic functions: 1e-13.
constexpr double kExactAgreement = 1e-13;

TEST(SpinSplit, ExactForSymmetricFreeBody) {
  const QuadraticModel model{Body::from_principal(Vec3(1.0, 1.0, 1.7), 1.0, Vec3::Zero()),
                             QuadraticField{}};
  const State x0 =
      state_from_omega(model.body, Vec3(0.4, -0.7, 1.2), Vec3(0.3, 0.5, 0.8).normalized());
  // By moment: 0, 1 the equal axes, 2 the largest; reference axis (axes[2]) = 1.
  SplittingStepper s(composition_table("splitting2"),
                     SplitOrdering{{2, 0, 1}, false, true, FreeBodySplit::spin});
  State x = x0;
  s.step(model, x, 3.7);
  const State ref = free_body_flow(model.body, x0, 3.7);
  EXPECT_LT(test::distance(x, ref), kExactAgreement);
  // The same split about the largest axis is not exact: the check above can fail.
  SplittingStepper other(composition_table("splitting2"),
                         SplitOrdering{{0, 1, 2}, false, true, FreeBodySplit::spin});
  State y = x0;
  other.step(model, y, 3.7);
  EXPECT_GT(test::distance(y, ref), 1e3 * kExactAgreement) << "largest axis as reference";
}

TEST(SplitFrame, IsAProperSignedPermutationPuttingTheAxesInOrder) {
  const Body body =
      Body::from_principal(Vec3(2.2, 1.0, 1.5), 1.0, Vec3::Zero(), Vec3(0.1, 0.2, 0.3));
  for (const auto& axes : {std::array<int, 3>{0, 1, 2}, {1, 0, 2}, {2, 1, 0}, {0, 2, 1}}) {
    const SplitFrame f = split_frame(body, SplitOrdering{axes, false, true, FreeBodySplit::axes});
    Mat3 P = Mat3::Zero();
    for (int w = 0; w < 3; ++w) P(w, f.axis[w]) = f.sign[w];
    EXPECT_DOUBLE_EQ(P.determinant(), 1.0);
    // Working axis w has the moment of rank axes[w].
    Vec3 sorted = body.inertia();
    std::sort(sorted.data(), sorted.data() + 3);
    for (int w = 0; w < 3; ++w) EXPECT_EQ(body.inertia()[f.axis[w]], sorted[axes[w]]);
    for (int w = 0; w < 3; ++w) {
      EXPECT_DOUBLE_EQ(f.k_over_i[w], (P * body.gyrostat())[w] / body.inertia()[f.axis[w]]);
    }
  }
}

// A near-integrable table's kicks at the cumulative flow times form a quadrature rule on [0, 1];
// its O(ε) error is that of the rule, so SABA_n and SBAB_n must integrate t^j exactly for
// j < 2n (Gauss, Lobatto), to the rounding of the coefficients: 8 ε.
TEST(NearIntegrableTables, KicksFormTheQuadratureRule) {
  for (const auto& [name, n] : {std::pair{"saba2", 2},
                                {"saba3", 3},
                                {"saba4", 4},
                                {"sbab2", 2},
                                {"sbab3", 3},
                                {"sbab4", 4}}) {
    const CompositionTable& t = composition_table(name);
    ASSERT_EQ(t.b.size(), t.a.size() + 1);
    for (int j = 0; j < 2 * n; ++j) {
      double sum = 0, time = 0;
      for (std::size_t i = 0; i < t.b.size(); ++i) {
        sum += t.b[i] * std::pow(time, j);
        if (i < t.a.size()) time += t.a[i];
      }
      EXPECT_NEAR(sum, 1.0 / (j + 1), 8 * kEps) << name << " t^" << j;
      EXPECT_NEAR(time, 1.0, 8 * kEps) << name;
    }
  }
}

// The published ABA(8,6,4) and ABA(10,6,4) coefficients: consistent (Σa = Σb = 1) and symmetric.
TEST(NearIntegrableTables, PublishedMethodsAreConsistentAndSymmetric) {
  for (const char* name : {"aba864", "aba1064"}) {
    const CompositionTable& t = composition_table(name);
    double sa = 0, sb = 0;
    for (double a : t.a) sa += a;
    for (double b : t.b) sb += b;
    EXPECT_NEAR(sa, 1.0, 1e-15) << name;
    EXPECT_NEAR(sb, 1.0, 1e-15) << name;
    for (std::size_t i = 0; i < t.a.size(); ++i) EXPECT_EQ(t.a[i], t.a[t.a.size() - 1 - i]);
    for (std::size_t i = 0; i < t.b.size(); ++i) EXPECT_EQ(t.b[i], t.b[t.b.size() - 1 - i]);
  }
}

TEST(NearIntegrableTables, NeedTheExactFreeBody) {
  EXPECT_THROW(SplittingStepper(composition_table("sbab3"), SplitOrdering{}), InputError);
}

}  // namespace
}  // namespace test_sub_flows
}  // namespace newtop
