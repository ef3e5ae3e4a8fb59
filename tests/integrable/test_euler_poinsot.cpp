// Euler–Poinsot: the Jacobi-elliptic solution of the free rigid body against an independent
// high-accuracy integration (Fehlberg 7(8)), in every regime: circulation about the largest and the
// smallest axis, symmetric bodies, permanent rotations.

// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <gtest/gtest.h>

#include <cmath>

#include "newtop/analysis/euler_poinsot.hpp"
#include "newtop/integrate/methods.hpp"

namespace newtop {
namespace test_euler_poinsot {
namespace {

// rkf78 at tolerance 1e-14 over a few periods keeps a global error near 1e-12 (|m| ~ 1); the
// analytic solution is accurate to a few ulps times the number of elliptic-function evaluations;
// 1e-10 (the target) leaves a factor ~100 of margin over the reference's own error.
constexpr double kAgreement = 1e-10;
constexpr double kReferenceTol = 1e-14;

State reference(const QuadraticModel& model, const State& x0, double t) {
  Fehlberg78Stepper s(kReferenceTol, kReferenceTol);
  return integrate(s, model, x0, 0.0, t, {}).state;
}

QuadraticModel free_model(const Vec3& I) {
  return QuadraticModel{Body::from_principal(I, 1.0, Vec3::Zero()), QuadraticField{}};
}

double max_error(const QuadraticModel& model, const State& x0, double t_end, int samples) {
  const EulerPoinsot sol = euler_poinsot(model.body, x0);
  double err = 0.0;
  State x = x0;
  for (int i = 1; i <= samples; ++i) {
    const double t0 = t_end * (i - 1) / samples, t1 = t_end * i / samples;
    x = [&] {
      Fehlberg78Stepper s(kReferenceTol, kReferenceTol);
      return integrate(s, model, x, t0, t1, {}).state;
    }();
    const State a = free_body_state(sol, t1);
    EXPECT_TRUE(a.m.allFinite() && a.gamma.allFinite());
    err = std::max({err, (a.m - x.m).norm(), (a.gamma - x.gamma).norm()});
  }
  return err;
}

struct Case {
  const char* name;
  Vec3 inertia;
  Vec3 omega;
  Vec3 gamma;
};

class EulerPoinsotCases : public ::testing::TestWithParam<Case> {};

TEST_P(EulerPoinsotCases, MatchesNumericalMotionOverSeveralPeriods) {
  const Case& c = GetParam();
  const QuadraticModel model = free_model(c.inertia);
  const State x0 = state_from_omega(model.body, c.omega, c.gamma.normalized());
  const EulerPoinsot sol = euler_poinsot(model.body, x0);
  const double t_end = std::isfinite(sol.period) ? 3.3 * sol.period : 20.0;
  EXPECT_LT(max_error(model, x0, t_end, 40), kAgreement * std::max(1.0, x0.m.norm()));
}

INSTANTIATE_TEST_SUITE_P(
    Regimes, EulerPoinsotCases,
    ::testing::Values(
        Case{"about_largest_axis", {1.0, 2.0, 3.0}, {0.3, 0.4, 1.1}, {0.2, -0.5, 0.8}},
        Case{"about_smallest_axis", {1.0, 2.0, 3.0}, {1.5, 0.4, -0.2}, {0.6, 0.6, 0.5}},
        Case{"descending_order", {3.0, 1.2, 2.5}, {0.1, -0.9, 0.3}, {-0.3, 0.1, 0.9}},
        Case{"near_separatrix", {1.0, 2.0, 3.0}, {0.01, 1.0, 0.012}, {0.0, 0.6, 0.8}},
        Case{"symmetric_prolate", {2.0, 2.0, 1.0}, {0.5, 0.1, 3.0}, {0.5, 0.0, 0.87}},
        Case{"symmetric_oblate", {1.0, 2.0, 2.0}, {0.2, 0.7, -0.4}, {0.0, 0.0, 1.0}},
        Case{"permanent_axis", {1.0, 2.0, 3.0}, {0.0, 0.0, 2.0}, {0.6, 0.0, 0.8}},
        Case{"permanent_equatorial_symmetric", {2.0, 2.0, 1.0}, {0.6, 0.8, 0.0}, {0, 0.6, 0.8}},
        Case{"sphere", {1.0, 1.0, 1.0}, {0.3, -0.2, 0.5}, {1.0, 0.0, 0.0}}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(EulerPoinsot, PeriodIsThePeriodOfTheAngularMomentum) {
  const QuadraticModel model = free_model({1.0, 2.0, 3.0});
  const State x0 = state_from_omega(model.body, {0.3, 0.4, 1.1}, {0.0, 0.0, 1.0});
  const EulerPoinsot sol = euler_poinsot(model.body, x0);
  ASSERT_TRUE(std::isfinite(sol.period));
  const State x = reference(model, x0, sol.period);
  EXPECT_LT((x.m - x0.m).norm(), kAgreement);
  // Half a period is not a period: the test can fail.
  EXPECT_GT((reference(model, x0, 0.5 * sol.period).m - x0.m).norm(), 0.1);
}

TEST(EulerPoinsot, RejectsGyrostat) {
  const Body b = Body::from_principal({1.0, 2.0, 3.0}, 1.0, Vec3::Zero(), {0.0, 0.0, 0.1});
  EXPECT_THROW(euler_poinsot(b, State{}), InputError);
}

}  // namespace
}  // namespace test_euler_poinsot
}  // namespace newtop
