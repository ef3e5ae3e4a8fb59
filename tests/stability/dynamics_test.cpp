// The verdicts against the dynamics: permanent rotations (every family of docs/model.md §8)
// integrate to stay put, pushed unstable ones depart, pushed stable ones stay within a bound ∝ the
// push.

#include <gtest/gtest.h>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/rotations.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "support.hpp"

namespace newtop {
namespace test_dynamics_test {
namespace {

using stability_test::max_departure;

// A fixed point integrated by Fehlberg 7(8): the state's own round-off (~1e-16) grows at most like
// e^{ρT} with ρ the largest real part; rotations used here have ρT ≤ 10, e^10 ≈ 2.2e4, so
// 1e-16 · 2.2e4 · (a few units of state size) stays below the 1e-10 over T = 10.
constexpr double kStayPut = 1e-10;
constexpr double kStayTime = 10.0;
constexpr double kMaxGrowth = 1.0;  // ρ ≤ 1 so that ρ T ≤ 10
// Linear stable motion about a fixed point is bounded by the push times the condition number of
// the eigenvector basis (moments within a factor 2.6 and Ω ~ √λ: of order ten); 100 is a bound a
// departing motion breaks at once.
constexpr double kStableAmplification = 100.0;
// An unstable motion grows like e^{ρt}: after t = 15/ρ the push is amplified ~3e6 unless the
// nonlinearity saturates it at O(1); either way it exceeds 1e4 pushes.
constexpr double kDepartFactor = 1e4;

QuadraticModel model_with(const Vec3& I, const Vec3& r0, double lambda) {
  return QuadraticModel{Body::from_principal(I, 1.0, r0), QuadraticField::coulomb(1.0, lambda)};
}

TEST(PermanentRotations, PrincipalAxisSpinsStayPutAtAnyOmega) {
  // r0 = 0: every principal axis; r0 along e_z: ±e_z (docs/model.md §8).
  const QuadraticModel brun = model_with(Vec3(1.0, 1.6, 2.1), Vec3::Zero(), 0.8);
  const QuadraticModel axial = model_with(Vec3(1.0, 1.6, 2.1), Vec3(0, 0, 0.3), 0.8);
  EXPECT_EQ(permanent_rotations(brun, 8).principal_axes.size(), 6u);
  EXPECT_EQ(permanent_rotations(axial, 8).principal_axes.size(), 2u);
  for (const QuadraticModel* m : {&brun, &axial}) {
    for (const Vec3& axis : permanent_rotations(*m, 8).principal_axes) {
      for (double w : {0.3, 1.1, 2.0}) {
        const State s = permanent_rotation(m->body, axis, w);
        if (linear_stability(*m, s).max_real_part > kMaxGrowth) continue;
        EXPECT_LE(max_departure(*m, s, kStayTime), kStayPut) << axis.transpose() << " " << w;
      }
    }
  }
}

TEST(PermanentRotations, AnyAxisAtRootLambdaStaysPut) {
  const QuadraticModel m = model_with(Vec3(1.0, 1.6, 2.1), Vec3::Zero(), 1.7);
  const RotationFamilies f = permanent_rotations(m, 8);
  ASSERT_TRUE(f.any_axis_omega.has_value());
  EXPECT_EQ(*f.any_axis_omega, std::sqrt(1.7));
  std::mt19937 rng(7);
  for (int k = 0; k < 4; ++k) {
    const State s = permanent_rotation(m.body, stability_test::random_unit(rng),
                                       (k % 2 ? -1 : 1) * *f.any_axis_omega);
    EXPECT_LE(fixed_point_residual(m, s), 64 * stability_test::kEps);
    EXPECT_LE(max_departure(m, s, kStayTime), kStayPut);
  }
}

TEST(PermanentRotations, StaudeConeAxesStayPut) {
  // Generic r0 and a case with x0 = 0 (the cone splits into two planes).
  for (const Vec3& r0 : {Vec3(0.3, -0.2, 0.25), Vec3(0.0, 0.3, -0.2)}) {
    const QuadraticModel m = model_with(Vec3(1.0, 1.6, 2.1), r0, 1.0);
    const RotationFamilies f = permanent_rotations(m, 24);
    ASSERT_FALSE(f.cone.empty());
    int integrated = 0, inadmissible = 0;
    for (const ConeAxis& c : f.cone) {
      EXPECT_LE(std::abs(staude_cone(m.body, c.gamma)), 64 * stability_test::kEps);
      if (!c.admissible) {
        ++inadmissible;
        continue;
      }
      const State s = permanent_rotation(m.body, c.gamma, std::sqrt(c.omega_squared));
      EXPECT_LE(fixed_point_residual(m, s), 1e3 * stability_test::kEps);
      if (c.omega_squared > 9.0 || linear_stability(m, s).max_real_part > kMaxGrowth) continue;
      if (integrated++ % 5 != 0) continue;  // every fifth admissible axis keeps the test fast
      EXPECT_LE(max_departure(m, s, kStayTime), kStayPut) << c.gamma.transpose();
    }
    EXPECT_GT(integrated, 5);
    EXPECT_GT(inadmissible, 0);  // Ω² < 0 occurs on the cone and is flagged
  }
}

TEST(StabilityDynamics, StableSpinStaysWithinABoundProportionalToThePush) {
  const QuadraticModel m = model_with(Vec3(2.0, 2.6, 1.2), Vec3::Zero(), 1.0);  // C least: stable
  const State s = principal_spin(m.body, 2, 1.3);
  ASSERT_TRUE(linear_stability(m, s).linearly_stable);
  for (double push : {1e-6, 1e-4}) {
    State p = s;
    p.m += push * Vec3(1.0, -0.7, 0.3);
    p.gamma = (p.gamma + push * Vec3(0.4, 0.9, 0.0)).normalized();
    EXPECT_LE(max_departure(m, p, 60.0), kStableAmplification * push);
  }
}

TEST(StabilityDynamics, UnstableSpinDeparts) {
  const QuadraticModel m =
      model_with(Vec3(1.0, 2.2, 1.6), Vec3::Zero(), 1.0);  // C middle: unstable
  const State s = principal_spin(m.body, 2, 1.5);
  const Spectrum sp = linear_stability(m, s);
  ASSERT_FALSE(sp.linearly_stable);
  ASSERT_EQ(sp.lyapunov_stable, std::optional<bool>(false));
  const double push = 1e-8;
  State p = s;
  p.m += push * Vec3(1.0, -0.7, 0.3);
  EXPECT_GE(max_departure(m, p, 15.0 / sp.max_real_part), kDepartFactor * push);
}

TEST(StabilityDynamics, EquilibriaVerdictsMatchPotentialType) {
  // At rest: a minimum of V is Lyapunov stable (energy–Casimir), a saddle or maximum is linearly
  // unstable (a real pair s² = −h/I > 0), and a pushed minimum stays close.
  const QuadraticModel m = model_with(Vec3(1.0, 1.6, 2.1), Vec3(0.2, -0.1, 0.15), 1.0);
  for (const Equilibrium& e : find_equilibria(m).equilibria) {
    const State s = state_from_omega(m.body, Vec3::Zero(), e.gamma);
    EXPECT_LE(fixed_point_residual(m, s), 64 * stability_test::kEps);
    const Spectrum sp = linear_stability(m, s);
    const bool minimum = e.type == EquilibriumType::minimum;
    EXPECT_EQ(sp.linearly_stable, minimum) << to_string(e.type);
    EXPECT_EQ(sp.lyapunov_stable, std::optional<bool>(minimum));
    if (minimum) {
      State p = s;
      p.m += 1e-6 * Vec3(0.3, 0.5, -0.2);
      EXPECT_LE(max_departure(m, p, 40.0), kStableAmplification * 1e-6);
    }
  }
}

TEST(StabilityDynamics, ResidualRejectsStatesThatAreNotFixedPoints) {
  const QuadraticModel m = model_with(Vec3(1.0, 1.6, 2.1), Vec3(0.2, -0.1, 0.15), 1.0);
  const State s = state_from_omega(m.body, Vec3(0.1, 0.2, 0.3), Vec3(0.6, 0.0, 0.8));
  EXPECT_GT(fixed_point_residual(m, s), 1e3 * kFixedPointTolerance);
}

}  // namespace
}  // namespace test_dynamics_test
}  // namespace newtop
