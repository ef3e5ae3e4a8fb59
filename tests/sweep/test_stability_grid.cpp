// The two-parameter stability diagram of a spin (sweep::stability_grid) against Beletsky's closed
// form of the threshold Ω* (docs/model.md §9), the same bits for any thread count, and the
// nonphysical points where the moments break the triangle inequality.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "newtop/analysis/stability_spin.hpp"
#include "newtop/sweep/stability_grid.hpp"

namespace newtop {
namespace test_stability_grid {
namespace {

/// Spin about z, the largest moment, centre of mass at O: Beletsky's case.
QuadraticModel beletsky_model(double lambda) {
  return QuadraticModel{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                        QuadraticField::coulomb(1.0, lambda)};
}

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v;
  for (int k = 0; k < n; ++k) v.push_back(a + (b - a) * k / (n - 1));
  return v;
}

// Points within this relative distance of Ω* are left out: there the largest real part is a
// square root of the distance, ~1e-8 at 1e-16 relative, and the spectral test's own tolerance
// decides.
constexpr double kThresholdMargin = 1e-3;

TEST(StabilityGrid, VerdictFollowsBeletskysThresholdOverOmegaAndLambda) {
  const QuadraticModel m = beletsky_model(1.0);
  const sweep::Axis omega{"omega", linspace(0.0, 3.0, 31)};
  const sweep::Axis lambda{"lambda", linspace(0.25, 2.0, 8)};
  const StabilityGrid g = sweep::stability_grid(m, 2, 0.0, omega, lambda);
  ASSERT_EQ(g.verdict.size(), omega.values.size() * lambda.values.size());
  int checked = 0;
  for (std::size_t i = 0; i < omega.values.size(); ++i) {
    for (std::size_t k = 0; k < lambda.values.size(); ++k) {
      const double w = omega.values[i];
      const auto star = beletsky_threshold(m.body, lambda.values[k], 2);
      ASSERT_TRUE(star.has_value());
      if (std::abs(w - *star) < kThresholdMargin * *star) continue;
      const GridVerdict v = g.verdict[i * lambda.values.size() + k];
      EXPECT_EQ(v, w > *star ? GridVerdict::stable : GridVerdict::unstable)
          << "omega " << w << " lambda " << lambda.values[k] << " threshold " << *star;
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
}

TEST(StabilityGrid, SameBitsForAnyThreadCount) {
  const QuadraticModel m = beletsky_model(1.0);
  const sweep::Axis a{"A", linspace(0.5, 2.5, 9)};
  const sweep::Axis w{"omega", linspace(0.0, 2.0, 13)};
  const StabilityGrid one = sweep::stability_grid(m, 2, 0.0, a, w, 1);
  const StabilityGrid three = sweep::stability_grid(m, 2, 0.0, a, w, 3);
  ASSERT_EQ(one.max_real_part.size(), three.max_real_part.size());
  EXPECT_EQ(std::memcmp(one.max_real_part.data(), three.max_real_part.data(),
                        one.max_real_part.size() * sizeof(double)),
            0);
  EXPECT_EQ(one.verdict, three.verdict);
}

TEST(StabilityGrid, MomentsBreakingTheTriangleInequalityAreNonphysical) {
  const QuadraticModel m = beletsky_model(1.0);  // B = 1.5, C = 2.2: A + B ≥ C needs A ≥ 0.7
  const StabilityGrid g = sweep::stability_grid(m, 2, 1.0, {"A", {0.5, 1.0}}, {"lambda", {1.0}});
  EXPECT_EQ(g.verdict[0], GridVerdict::nonphysical);
  EXPECT_TRUE(std::isnan(g.max_real_part[0]));
  EXPECT_NE(g.verdict[1], GridVerdict::nonphysical);
  EXPECT_THROW(sweep::stability_grid(m, 2, 1.0, {"mass", {1.0}}, {"A", {1.0}}), InputError);
}

}  // namespace
}  // namespace test_stability_grid
}  // namespace newtop
