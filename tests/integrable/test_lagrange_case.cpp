// The Lagrange-like case (docs/model.md §6): γ3(t) as an elliptic function of the quartic, the
// other angles by quadrature, against an independent numerical integration; the nutation period
// against event detection; r constant.

// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "event_period.hpp"
#include "newtop/analysis/lagrange_attitude.hpp"
#include "newtop/analysis/lagrange_case.hpp"
#include "newtop/integrate/methods.hpp"

namespace newtop {
namespace test_lagrange_case {
namespace {

// rkf78 at 1e-14: global error ~1e-12 over a few nutation periods; 1e-10 is the target.
constexpr double kAgreement = 1e-10;
constexpr double kReferenceTol = 1e-14;
// Event times from the dense output of dopri5 at 1e-13, bisected to 1e-15: error ~1e-10 in time.
constexpr double kPeriodAgreement = 1e-8;

struct Case {
  const char* name;
  Vec3 inertia;
  double mass_g, z0, lambda, k3;
  Vec3 omega, gamma;
};

QuadraticModel make_model(const Case& c) {
  return QuadraticModel{Body::from_principal(c.inertia, 1.0, {0, 0, c.z0}, {0, 0, c.k3}),
                        QuadraticField::coulomb(c.mass_g, c.lambda)};
}

class LagrangeCases : public ::testing::TestWithParam<Case> {};

TEST_P(LagrangeCases, MatchesNumericalMotionAndPeriod) {
  const Case& c = GetParam();
  const QuadraticModel model = make_model(c);
  const State x0 = state_from_omega(model.body, c.omega, c.gamma.normalized());
  const LagrangeCase sol = lagrange_case(model, x0);
  ASSERT_FALSE(sol.steady);
  ASSERT_TRUE(std::isfinite(sol.nutation_period));
  // The quartic vanishes at the turning values and is positive between them.
  const auto& q = sol.quartic.coefficient;
  auto F = [&](double u) { return (((q[4] * u + q[3]) * u + q[2]) * u + q[1]) * u + q[0]; };
  EXPECT_GT(F(0.5 * (sol.u1 + sol.u2)), 0.0);
  constexpr double kRootRounding = 1e-14;  // polished roots, a few ulps of γ3 ~ 1
  EXPECT_LE(std::min(sol.u1, sol.u2), x0.gamma.z() + kRootRounding);
  EXPECT_GE(std::max(sol.u1, sol.u2), x0.gamma.z() - kRootRounding);

  const double t_end = 3.4 * sol.nutation_period;
  const int samples = 30;
  State x = x0;
  double err = 0, r_drift = 0;
  for (int i = 1; i <= samples; ++i) {
    Fehlberg78Stepper s(kReferenceTol, kReferenceTol);
    x = integrate(s, model, x, t_end * (i - 1) / samples, t_end * i / samples, {}).state;
    const State a = lagrange_state(sol, t_end * i / samples);
    ASSERT_TRUE(a.m.allFinite() && a.gamma.allFinite());
    err = std::max({err, (a.m - x.m).norm(), (a.gamma - x.gamma).norm()});
    r_drift = std::max(r_drift, std::abs(omega(model.body, x).z() - sol.quartic.r));
  }
  EXPECT_LT(err, kAgreement * std::max(1.0, x0.m.norm())) << c.name;
  EXPECT_LT(r_drift, kAgreement * std::max(1.0, std::abs(sol.quartic.r)));

  // Nutation period: spacing of successive upward crossings of γ̇3 = q γ1 − p γ2 (minima of γ3).
  const auto times = test::upward_crossings(model, x0, t_end, [&](const State& s) {
    const Vec3 w = omega(model.body, s);
    return w.y() * s.gamma.x() - w.x() * s.gamma.y();
  });
  ASSERT_GE(times.size(), 2u);
  const double measured = (times.back() - times.front()) / double(times.size() - 1);
  EXPECT_NEAR(measured, sol.nutation_period, kPeriodAgreement * sol.nutation_period);
}

// The closed form's Euler angles (precession about the fixed direction e, nutation, spin) against
// the attitude integrated by rkf78 at 1e-14 beside (m, γ): the attitude in the frame N of the
// closed form is R_N(t) = R_N(0) R(0)ᵀ R(t), whatever the initial attitude R(0). The angles agree
// to the state's kAgreement, over sin θ for the outer angles (they are the attitude's error divided
// by sin θ near the poles).
TEST_P(LagrangeCases, EulerAnglesMatchIntegratedAttitude) {
  const Case& c = GetParam();
  const QuadraticModel model = make_model(c);
  const State x0 = state_from_omega(model.body, c.omega, c.gamma.normalized());
  const LagrangeCase sol = lagrange_case(model, x0);
  const Quaternion q0 = from_euler_321(Vec3(-0.3, 0.9, 1.7));
  const Quaternion n0 = from_euler_313(lagrange_euler_angles(sol, 0.0));
  const double t_end = 2.3 * sol.nutation_period;
  const int samples = 20;
  OrientedState x = with_attitude(x0, q0);
  double worst = 0, min_sin = 1;
  for (int i = 1; i <= samples; ++i) {
    Fehlberg78Stepper s(kReferenceTol, kReferenceTol);
    const Outcome out = integrate(s, model, x, t_end * (i - 1) / samples, t_end * i / samples, {});
    x = with_attitude(out.state, *out.attitude);
    const Vec3 closed = lagrange_euler_angles(sol, t_end * i / samples);
    const Vec3 integrated = euler_313(n0 * q0.conjugate() * x.q);
    min_sin = std::min(min_sin, std::sin(closed[1]));
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst,
                       std::abs(std::remainder(closed[k] - integrated[k], 2 * std::numbers::pi)));
    }
  }
  ASSERT_GT(min_sin, 0.1) << c.name;
  EXPECT_LT(worst, kAgreement * std::max(1.0, x0.m.norm()) / min_sin) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    Tops, LagrangeCases,
    ::testing::Values(
        Case{"heavy_top", {2, 2, 1}, 9.81, 0.5, 0.0, 0.0, {0.3, 0.0, 20.0}, {0.5, 0.0, 0.866}},
        Case{"slow_heavy_top", {2, 2, 1}, 9.81, 0.5, 0.0, 0.0, {0.3, -0.4, 1.0}, {0.5, 0.3, 0.7}},
        Case{
            "newtonian_oblate", {1, 1, 1.8}, 2.0, -0.3, 3.0, 0.0, {0.4, 0.1, 1.5}, {0.2, 0.6, 0.7}},
        Case{"newtonian_prolate", {2, 2, 0.7}, 1.0, 0.4, 2.5, 0.0, {-0.5, 0.3, 0.9}, {0.7, 0, 0.7}},
        Case{
            "gravity_gradient_only", {1.5, 1.5, 0.6}, 0, 0, 4.0, 0.0, {0.2, 0.5, 1}, {0, 0.6, 0.8}},
        Case{"gyrostat", {2, 2, 1}, 3.0, 0.5, 1.0, 0.7, {0.3, 0.2, 2.0}, {0.4, -0.3, 0.866}},
        Case{"from_turning_point", {2, 2, 1}, 9.81, 0.5, 0.0, 0.0, {0.0, 0.0, 5.0}, {0, 0.6, 0.8}}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(LagrangeCase, QuarticCoefficientsMatchSpec) {
  // Spec §6: γ̇3² = F(γ3) with E, a, a1, b, c; checked against γ̇3 computed from the state.
  const Case c{"x", {2, 2, 1}, 3.0, 0.5, 1.5, 0.0, {0.3, 0.2, 2.0}, {0.4, -0.3, 0.866}};
  const QuadraticModel model = make_model(c);
  const State x0 = state_from_omega(model.body, c.omega, c.gamma.normalized());
  const LagrangeQuartic Q = lagrange_quartic(model, x0);
  const double u = x0.gamma.z();
  const double F = (1 - u * u) * (Q.E - Q.a * u - Q.a1 * u * u) - std::pow(Q.b - Q.c * Q.r * u, 2);
  const Vec3 w = omega(model.body, x0);
  const double u_dot = w.y() * x0.gamma.x() - w.x() * x0.gamma.y();
  constexpr double kRoundoff = 1e-13;  // a few ulps of the O(10) terms of F
  EXPECT_NEAR(F, u_dot * u_dot, kRoundoff);
  EXPECT_DOUBLE_EQ(Q.a1, 1.5 * (1.0 - 2.0) / 2.0);
  EXPECT_DOUBLE_EQ(Q.c, 0.5);
}

TEST(LagrangeCase, RejectsAsymmetricBody) {
  const QuadraticModel model{Body::from_principal({1, 2, 3}, 1.0, Vec3::Zero()), QuadraticField{}};
  EXPECT_THROW(lagrange_case(model, State{}), InputError);
}

}  // namespace
}  // namespace test_lagrange_case
}  // namespace newtop
