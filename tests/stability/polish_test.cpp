// polish_fixed_point: Newton's method brings a fixed point given to a few digits back to
// round-off, keeps the kind of motion (rest, spin rate), and refuses a state that is no fixed
// point to three digits.

#include <gtest/gtest.h>

#include <cmath>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/rotations.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "support.hpp"

namespace newtop {
namespace test_polish_test {
namespace {

using stability_test::kEps;

// Residual of a polished fixed point: Newton converges quadratically to round-off, and the
// residual of a state correct to round-off is a few ulps of its terms relative to their scale
// (the scales of fixed_point_residual): 64 ε.
constexpr double kPolishedResidual = 64 * kEps;
// The polished state against the exact fixed point: round-off amplified by the conditioning of
// the fixed-point equations, which for these bodies (moments within a factor 2.1, r0 ~ 0.2) is
// O(10): 1e3 ε.
constexpr double kPolishedError = 1e3 * kEps;

/// Each component of x rounded to `digits` significant digits, as a user copying values would.
Vec3 rounded(const Vec3& x, int digits) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    if (x[i] == 0.0) {
      r[i] = 0.0;
      continue;
    }
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(std::abs(x[i]))));
    r[i] = std::round(x[i] * scale) / scale;
  }
  return r;
}

QuadraticModel model_with(const Vec3& I, const Vec3& r0, double lambda) {
  return QuadraticModel{Body::from_principal(I, 1.0, r0), QuadraticField::coulomb(1.0, lambda)};
}

TEST(PolishFixedPoint, SevenDigitEquilibriaReturnToRoundOff) {
  // Every equilibrium of a body with r0 off every axis, copied to 7 digits: a residual ~1e-7
  // (above kFixedPointTolerance), polished to round-off at rest, onto the listed equilibrium.
  const QuadraticModel m = model_with(Vec3(1.0, 1.6, 2.1), Vec3(0.05, -0.03, 0.02), 1.0);
  const EquilibriumSet set = find_equilibria(m);
  ASSERT_EQ(set.equilibria.size(), 6u);
  for (const Equilibrium& e : set.equilibria) {
    const State copy = state_from_omega(m.body, Vec3::Zero(), rounded(e.gamma, 7));
    ASSERT_GT(fixed_point_residual(m, copy), kFixedPointTolerance);
    const PolishedFixedPoint p = polish_fixed_point(m, copy);
    EXPECT_TRUE(p.converged);
    EXPECT_GT(p.iterations, 0);
    EXPECT_LE(p.residual, kPolishedResidual);
    EXPECT_LE((p.state.gamma - e.gamma).norm(), kPolishedError) << to_string(e.type);
    EXPECT_EQ(p.state.m, copy.m);  // stays at rest
    EXPECT_NEAR(p.correction, (copy.gamma - e.gamma).norm(), kPolishedError);
    EXPECT_EQ(p.residual_given, fixed_point_residual(m, copy));
  }
}

TEST(PolishFixedPoint, SpinAboutAPrincipalAxisKeepsItsRate) {
  // The spin of stability_beletsky.toml with γ and ω pushed by 1e-6: the nearest fixed point is
  // the spin about e_z, and Ω moves by no more than the push (the family is Ω itself).
  const QuadraticModel m = model_with(Vec3(1.0, 1.5, 2.2), Vec3::Zero(), 1.0);
  const State exact = principal_spin(m.body, 2, 1.2);
  const State pushed =
      state_from_omega(m.body, Vec3(2e-6, -1e-6, 1.2 + 1e-6), Vec3(1e-6, 3e-7, 1.0));
  const PolishedFixedPoint p = polish_fixed_point(m, pushed);
  EXPECT_TRUE(p.converged);
  EXPECT_LE(p.residual, kPolishedResidual);
  EXPECT_LE((p.state.gamma - exact.gamma).norm(), kPolishedError);
  const Vec3 w = omega(m.body, p.state);
  EXPECT_LE(Vec3(w.x(), w.y(), 0).norm(), kPolishedError);
  EXPECT_LE(std::abs(w.z() - 1.2), 2e-6);
}

TEST(PolishFixedPoint, StaudeConeRotationReturnsToTheCone) {
  // A permanent rotation about an axis of the Staude cone (r0 ≠ 0), copied to 8 digits.
  const QuadraticModel m = model_with(Vec3(1.0, 1.6, 2.1), Vec3(0.3, -0.2, 0.25), 1.0);
  const RotationFamilies f = permanent_rotations(m, 24);
  int checked = 0;
  for (const ConeAxis& c : f.cone) {
    if (!c.admissible || c.omega_squared < 0.1 || c.omega_squared > 9.0) continue;
    const State exact = permanent_rotation(m.body, c.gamma, std::sqrt(c.omega_squared));
    const State copy{rounded(exact.m, 8), rounded(exact.gamma, 8)};
    if (fixed_point_residual(m, copy) <= kFixedPointTolerance) continue;
    const PolishedFixedPoint p = polish_fixed_point(m, copy);
    EXPECT_TRUE(p.converged) << c.gamma.transpose();
    EXPECT_LE(p.residual, kPolishedResidual) << c.gamma.transpose();
    // On the cone, and close to the copy: the family of cone rotations passes through it.
    EXPECT_LE(std::abs(staude_cone(m.body, p.state.gamma)), kPolishedResidual);
    EXPECT_LE(p.correction, 1e-7);
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(PolishFixedPoint, GyrostatAtRestStaysAtRest) {
  const QuadraticModel m{
      Body::from_principal(Vec3(1.0, 1.6, 2.1), 1.0, Vec3(0.2, -0.1, 0.15), Vec3(0.0, 0.0, 0.4)),
      QuadraticField::coulomb(1.0, 1.0)};
  const Equilibrium e = find_equilibria(m).equilibria.front();
  const State copy = state_from_omega(m.body, Vec3::Zero(), rounded(e.gamma, 6));
  const PolishedFixedPoint p = polish_fixed_point(m, copy);
  EXPECT_TRUE(p.converged);
  EXPECT_EQ(p.state.m, m.body.gyrostat());
  EXPECT_LE((p.state.gamma - e.gamma).norm(), kPolishedError);
}

TEST(PolishFixedPoint, RefusesAStateFarFromEveryFixedPoint) {
  // A tumbling state: Newton moves it by far more than kPolishRadius, or does not converge.
  const QuadraticModel m = model_with(Vec3(1.0, 1.6, 2.1), Vec3(0.2, -0.1, 0.15), 1.0);
  const State s = state_from_omega(m.body, Vec3(0.1, 0.2, 0.3), Vec3(0.6, 0.0, 0.8));
  const PolishedFixedPoint p = polish_fixed_point(m, s);
  EXPECT_FALSE(p.converged);
  // An exact fixed point is left as it is (to round-off).
  const Equilibrium e = find_equilibria(m).equilibria.front();
  const State rest = state_from_omega(m.body, Vec3::Zero(), e.gamma);
  const PolishedFixedPoint q = polish_fixed_point(m, rest);
  EXPECT_TRUE(q.converged);
  EXPECT_LE(q.correction, kPolishedError);
}

}  // namespace
}  // namespace test_polish_test
}  // namespace newtop
