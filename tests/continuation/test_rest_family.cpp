// The equilibria at rest of the fixed-point model continued in a key (docs/continuation.md §4b):
// the pitchforks where an off-axis pair merges into an axis (known exactly), and a saddle-node
// against the double root of the secular polynomial (docs/model.md §7).

#include <gtest/gtest.h>

#include <cmath>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/rest_family.hpp"

namespace newtop {
namespace test_rest_family {
namespace {

// As in test_continuation.cpp: 1e-10 in the parameter, the demand; the test functions
// here are algebraic (no integration), so only the corrector's 1e-12 and round-off remain.
constexpr double kLocated = 1e-10;

std::vector<BifurcationEvent> of_type(const Family& f, BifurcationType t) {
  std::vector<BifurcationEvent> out;
  for (const BifurcationEvent& e : f.events)
    if (e.type == t) out.push_back(e);
  return out;
}

QuadraticModel model(const Vec3& r0) {
  return {Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, r0), QuadraticField{1.0, 1.0}};
}

TEST(ContinuationRest, AxisEquilibriumHasPitchforksWhereTheOffAxisPairsMerge) {
  // r0 = (x, 0, 0), λ = g = M = 1, d = λI = (1, 1.5, 2.2): γ = e_x (κ = 1 + x) is an equilibrium
  // for every x; the off-axis pair of axis j (κ = d_j, γ_x = x/(d_j − 1)) reaches it where
  // γ_x = 1: at x = d_j − 1 = 0.5 and 1.2.
  const Family f = rest_family(quadratic_path(model(Vec3(0.1, 0, 0)), "body.center_of_mass[0]"),
                               Vec3::UnitX(), 0.1, 2.0);
  EXPECT_EQ(f.end, "range");
  const auto bp = of_type(f, BifurcationType::branch_point);
  ASSERT_EQ(bp.size(), 2u);
  EXPECT_TRUE(of_type(f, BifurcationType::fold).empty());
  EXPECT_NEAR(bp[0].value, 0.5, kLocated);
  EXPECT_NEAR(bp[1].value, 1.2, kLocated);
  for (const FamilyPoint& p : f.points) {
    EXPECT_NEAR(p.values[3], 1 + p.parameter, 1e-12);  // κ = d_x + x on the axis
    const char* expected = p.parameter < 0.5 ? "minimum" : p.parameter < 1.2 ? "saddle" : "maximum";
    if (std::abs(p.parameter - 0.5) > 1e-6 && std::abs(p.parameter - 1.2) > 1e-6) {
      EXPECT_EQ(p.stability, expected) << p.parameter;
    }
  }
}

TEST(ContinuationRest, SaddleNodeIsTheSecularPolynomialsDoubleRoot) {
  // r0 = (x, 0.05, 0): the first pitchfork unfolds; the minimum near e_x meets a saddle and both
  // vanish at a fold. Independently: P(κ; x) = 0 = ∂P/∂κ for the secular polynomial P of
  // docs/model.md §7, by Newton's method in (κ, x) (central-difference Jacobian) from 1e-3 away.
  auto at = [](double x) { return model(Vec3(x, 0.05, 0)); };
  const QuadraticPath path = quadratic_path(at(0.1), "body.center_of_mass[0]");
  const EquilibriumSet eq = find_equilibria(at(0.1));
  const Equilibrium* start = nullptr;
  for (const Equilibrium& e : eq.equilibria)
    if (e.type == EquilibriumType::minimum && e.gamma[0] > 0) start = &e;
  ASSERT_NE(start, nullptr);
  const Family f = rest_family(path, start->gamma, 0.1, 2.0);
  const auto folds = of_type(f, BifurcationType::fold);
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_EQ(f.end, "left_range");  // back to x = 0.1 as the saddle
  EXPECT_EQ(f.points.back().stability, "saddle");
  auto G = [&](const Eigen::Vector2d& y) {
    const Eigen::VectorXd c = secular_polynomial(at(y[1]));
    double p = 0, dp = 0;
    for (Eigen::Index i = c.size() - 1; i >= 0; --i) {
      dp = dp * y[0] + p;
      p = p * y[0] + c[i];
    }
    return Eigen::Vector2d(p, dp);
  };
  Eigen::Vector2d y(folds[0].point.values[3] + 1e-3, folds[0].value - 1e-3);
  for (int it = 0; it < 30; ++it) {
    Eigen::Matrix2d J;
    for (int i = 0; i < 2; ++i) {
      Eigen::Vector2d a = y, b = y;
      a[i] += 1e-6;
      b[i] -= 1e-6;
      J.col(i) = (G(a) - G(b)) / 2e-6;
    }
    const Eigen::Vector2d step = J.partialPivLu().solve(G(y));
    y -= step;
    if (step.norm() < 1e-15) break;
  }
  EXPECT_NEAR(folds[0].value, y[1], kLocated);
  EXPECT_NEAR(folds[0].point.values[3], y[0], 1e-6);  // κ varies like √ near a fold
  std::printf("fold at x = %.15f, secular double root at x = %.15f\n", folds[0].value, y[1]);
}

}  // namespace
}  // namespace test_rest_family
}  // namespace newtop
