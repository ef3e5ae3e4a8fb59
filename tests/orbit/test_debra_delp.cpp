// The DeBra–Delp diagram: the model's own linearisation at the rest orientation against the
// closed-form pitch and roll–yaw factors (DeBra & Delp 1961; Hughes §9.3), and the regions'
// verdicts against the closed-form conditions.

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "newtop/orbit/debra_delp.hpp"
#include "orbit_problems.hpp"

namespace newtop {
namespace test_debra_delp {
namespace {

using test::kOrbitEps;

// The characteristic polynomial is formed from the eigenvalues of the 6×6 leaf Jacobian (|J| ≤ 6
// in units of ω0 here): a backward-stable eigensolver perturbs J by ~16 ε|J|, which moves the
// coefficient of s^(6−k) by ~16 ε k |J|^k ≤ 16 · 6 · 6⁶ ε ≈ 1e-9 at worst (k = 6); the constant
// and s², s⁴ terms compared here are sums of products of eigenvalues of that size.
constexpr double kCharacteristicTolerance = 16 * 6 * 46656 * kOrbitEps;

TEST(DebraDelp, CharacteristicPolynomialIsPitchTimesRollYaw) {
  for (const auto& [k_R, k_Y] :
       {std::pair{0.5, 0.2}, std::pair{-0.05, -0.5}, std::pair{0.2, 0.5}, std::pair{-0.7, 0.4},
        std::pair{0.9, -0.95}, std::pair{-0.3, -0.8}}) {
    const DebraDelpPoint p = debra_delp_point(k_R, k_Y);
    ASSERT_TRUE(p.characteristic.allFinite());
    const Eigen::Vector4d sigma = debra_delp_characteristic(k_R, k_Y);
    for (int k = 0; k <= 3; ++k) {
      EXPECT_NEAR(p.characteristic[2 * k], sigma[k], kCharacteristicTolerance)
          << "s^" << 2 * k << " at k_R = " << k_R << ", k_Y = " << k_Y;
    }
    for (int k = 0; k < 3; ++k) {  // a Hamiltonian spectrum: no odd powers
      EXPECT_NEAR(p.characteristic[2 * k + 1], 0.0, kCharacteristicTolerance);
    }
  }
}

TEST(DebraDelp, NamedPointsGetTheirRegion) {
  struct Case {
    double k_R, k_Y;
    DebraDelpRegion region;
  };
  for (const Case& c :
       {Case{0.5, 0.2, DebraDelpRegion::lagrange}, Case{0.8, 0.79, DebraDelpRegion::lagrange},
        Case{-0.05, -0.5, DebraDelpRegion::debra_delp},
        Case{-0.02, -0.9, DebraDelpRegion::debra_delp},
        Case{0.2, 0.5, DebraDelpRegion::unstable},      // pitch: k_R < k_Y
        Case{-0.5, -0.6, DebraDelpRegion::unstable},    // roll–yaw: b1 < 0
        Case{-0.1, -0.5, DebraDelpRegion::unstable},    // roll–yaw: b1² < 4 b0
        Case{0.5, -0.3, DebraDelpRegion::unstable}}) {  // roll–yaw: k_R k_Y < 0
    const DebraDelpPoint p = debra_delp_point(c.k_R, c.k_Y);
    EXPECT_EQ(p.closed_form, c.region) << c.k_R << ", " << c.k_Y;
    EXPECT_EQ(p.computed, c.region) << c.k_R << ", " << c.k_Y;
  }
}

// Over a 61 × 61 grid of the square: a point whose eight neighbours share its closed-form region
// is well inside it and must get that verdict; a point next to a boundary must get the region of
// one of its neighbours (the computed boundary lies within a grid cell of the closed form). Points
// on a degenerate line (the grid hits k_Y = 0 and k_R = k_Y exactly, where a frequency vanishes)
// must be flagged as such, and are not judged: at k_R = k_Y = 0 (a sphere) every mode is neutral.
TEST(DebraDelp, ScanMatchesClosedFormWithinAGridCell) {
  constexpr int n = 61;
  constexpr double lo = -0.99, hi = 0.99;
  const std::vector<DebraDelpPoint> scan = debra_delp_scan(lo, hi, n, lo, hi, n);
  ASSERT_EQ(scan.size(), static_cast<std::size_t>(n * n));
  auto at = [&](int i, int j) -> const DebraDelpPoint& { return scan[i * n + j]; };
  std::map<DebraDelpRegion, int> inside;
  int boundary = 0, flagged = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const DebraDelpPoint& p = at(i, j);
      bool uniform = true, near = false;
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const int a = i + di, b = j + dj;
          if (a < 0 || b < 0 || a >= n || b >= n) continue;
          uniform = uniform && at(a, b).closed_form == p.closed_form;
          near = near || at(a, b).closed_form == p.computed;
        }
      }
      flagged += p.boundary;
      if (p.boundary) continue;  // degenerate: the linearisation decides nothing (e.g. k = 0)
      if (uniform) {
        EXPECT_EQ(p.computed, p.closed_form) << "k_R = " << p.k_R << ", k_Y = " << p.k_Y;
        ++inside[p.closed_form];
      } else {
        EXPECT_TRUE(near) << "k_R = " << p.k_R << ", k_Y = " << p.k_Y;
        ++boundary;
      }
    }
  }
  // Every region is sampled well inside (the DeBra–Delp region is a thin sliver along k_R = 0⁻).
  EXPECT_GE(inside[DebraDelpRegion::lagrange], 100);
  EXPECT_GE(inside[DebraDelpRegion::debra_delp], 3);
  EXPECT_GE(inside[DebraDelpRegion::unstable], 100);
  EXPECT_GT(boundary, 0);
  EXPECT_GE(flagged, 2 * n - 1);  // at least the grid points on k_Y = 0 and on k_R = k_Y
}

TEST(DebraDelp, RatiosOutsideTheSquareAreBadInput) {
  EXPECT_THROW(inertia_from_ratios(1.0, 0.2), InputError);
  EXPECT_THROW(inertia_from_ratios(0.2, -1.5), InputError);
  EXPECT_THROW(inertia_from_ratios(std::nan(""), 0.2), InputError);
  EXPECT_THROW(debra_delp_scan(-0.5, 1.2, 5, 0.0, 0.5, 5), InputError);
  EXPECT_THROW(debra_delp_scan(-0.5, 0.5, 0, 0.0, 0.5, 5), InputError);
  // The moments reproduce the ratios.
  const Vec3 I = inertia_from_ratios(-0.3, 0.6);
  EXPECT_NEAR((I.y() - I.z()) / I.x(), -0.3, 4 * kOrbitEps);
  EXPECT_NEAR((I.y() - I.x()) / I.z(), 0.6, 4 * kOrbitEps);
}

}  // namespace
}  // namespace test_debra_delp
}  // namespace newtop
