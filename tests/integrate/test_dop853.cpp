// Dormand–Prince 8(5,3): its published coefficients against the order conditions, the order of its
// step, its error control against an independent reference (Fehlberg 7(8) near round-off), a
// non-finite trial, the attitude it carries and the command line that names it.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "support/adaptive_checks.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_dop853 {
namespace {

namespace dp = dop853;
using test::kEps;

/// Rounding bound of a sum of n terms of the given magnitudes: each coefficient is the nearest
/// double to its decimal (ε/2 relative) and each product and addition rounds once more (ε/2 each):
/// 2 ε Σ|t_i| per term covers them all with room for the powers c^k (k ≤ 8 roundings, ≤ 4 ε).
double rounding_bound(const std::vector<double>& terms) {
  double s = 0.0;
  for (double t : terms) s += std::abs(t);
  return (2.0 + 0.5 * static_cast<double>(terms.size())) * kEps * s;
}

/// Σ_j w_j c_j^k and the bound of its rounding.
std::pair<double, double> moment(const double* w, int stages, int k) {
  std::vector<double> terms;
  for (int j = 0; j < stages; ++j) terms.push_back(w[j] * std::pow(dp::c[j], k));
  double s = 0.0;
  for (double t : terms) s += t;
  return {s, rounding_bound(terms)};
}

TEST(Dop853Tableau, NodesAreTheRowSums) {
  for (int i = 0; i < dp::kExtendedStages; ++i) {
    std::vector<double> row(dp::a[i], dp::a[i] + i);
    double s = 0.0;
    for (double v : row) s += v;
    EXPECT_NEAR(s, dp::c[i], rounding_bound(row)) << "row " << i;
  }
}

// The order-8 weights integrate c^(k−1) exactly for k ≤ 8 (the bushy trees), and b A c^(k−1) =
// 1/(k(k+1)) for k ≤ 7 (the trees of one branch point below the root): orders 8 and 8.
TEST(Dop853Tableau, WeightsSatisfyTheOrderConditions) {
  for (int k = 1; k <= 8; ++k) {
    const auto [s, tol] = moment(dp::b, dp::kStages, k - 1);
    EXPECT_NEAR(s, 1.0 / k, tol) << "b c^" << k - 1;
  }
  for (int k = 1; k <= 7; ++k) {
    std::vector<double> terms;
    for (int i = 0; i < dp::kStages; ++i) {
      for (int j = 0; j < i; ++j)
        terms.push_back(dp::b[i] * dp::a[i][j] * std::pow(dp::c[j], k - 1));
    }
    double s = 0.0;
    for (double t : terms) s += t;
    EXPECT_NEAR(s, 1.0 / (k * (k + 1)), rounding_bound(terms)) << "b A c^" << k - 1;
  }
}

// The error estimates: e5 = b − b̂ with b̂ of order 5, so Σ e5 c^(k−1) = 0 for k ≤ 5 and not for
// k = 6 (or it would be a higher-order estimate); the order-3 weights b̂̂ (bhh on stages 0, 8, 11)
// integrate c^(k−1) for k ≤ 3 and not k = 4.
TEST(Dop853Tableau, EmbeddedEstimatesHaveOrdersFiveAndThree) {
  for (int k = 1; k <= 6; ++k) {
    const auto [s, tol] = moment(dp::e5, dp::kStages, k - 1);
    if (k <= 5) {
      EXPECT_NEAR(s, 0.0, tol) << "e5 c^" << k - 1;
    } else {
      EXPECT_GT(std::abs(s), 1e3 * tol) << "e5 c^" << k - 1;
    }
  }
  double hat[dp::kStages] = {};
  hat[0] = dp::bhh[0], hat[8] = dp::bhh[1], hat[11] = dp::bhh[2];
  for (int k = 1; k <= 4; ++k) {
    const auto [s, tol] = moment(hat, dp::kStages, k - 1);
    if (k <= 3) {
      EXPECT_NEAR(s, 1.0 / k, tol) << "bhh c^" << k - 1;
    } else {
      EXPECT_GT(std::abs(s - 1.0 / k), 1e3 * tol) << "bhh c^" << k - 1;
    }
  }
}

/// The state at T after n equal steps of Dop853Stepper; a tolerance of 1e3 accepts every one of
/// these steps (asserted), so that the order observed is the formula's, not the controller's.
State fixed_steps(const QuadraticModel& m, const State& x0, double T, int n) {
  Dop853Stepper s(1e3, 1e3);
  State x = x0;
  double t = 0.0;
  for (int i = 0; i < n; ++i) {
    double dt = T / n;
    EXPECT_TRUE(s.try_step(m, x, t, dt)) << "step " << i << " of " << n << " rejected";
  }
  return x;
}

// Global error at T = 2 against Fehlberg 7(8) at 1e-14 for 4 and 8 steps: observed order within
// 0.5 of 8 (errors far above the reference's ~1e-14, checked).
TEST(Dop853, ObservedOrderIsEight) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const State x0 = test::generic_state(m);
  constexpr double T = 2.0;
  const State ref = test::reference_solution(m, x0, T, 1e-14);
  const double e1 = test::distance(fixed_steps(m, x0, T, 4), ref);
  const double e2 = test::distance(fixed_steps(m, x0, T, 8), ref);
  ASSERT_GT(e2, 1e-12) << "error at round-off, the order is not observable";
  EXPECT_NEAR(std::log2(e1 / e2), 8.0, 0.5) << "errors " << e1 << ", " << e2;
}

// The error control: over T = 10 of the generic model, the error at T against the reference falls
// with the tolerance — by at least 10× for each 100× (a controller of local error per step gives
// tol^(8/9), 60×) — and stays within kTolFactor tol. kTolFactor: each accepted step's RMS error
// estimate (of the embedded order-5 solution, above the propagated order-8 one's error) is ≤ tol
// in the weighted norm, and local errors grow along this orbit by e^(λT) ≈ 2.3 (λ ≈ 0.08); 10
// leaves room for the sum over steps (measured 2.5, 2.1, 1.5 tol).
constexpr double kTolFactor = 10.0;

TEST(Dop853, ErrorFollowsTheTolerance) {
  test::expect_error_follows_the_tolerance([](double tol) { return Dop853Stepper(tol, tol); },
                                           kTolFactor);
}

// A first trial of 10 time units overflows to NaN: the stepper rejects it and shrinks the step by
// kNonFiniteShrink, and the run ends on the reference.
TEST(Dop853, NonFiniteTrialIsRejected) {
  const QuadraticModel m = test::generic_model();
  const State x0 = test::generic_state(m);
  Dop853Stepper s(1e-12, 1e-12);
  State x = x0;
  double t = 0.0, dt = 1e3;
  EXPECT_FALSE(s.try_step(m, x, t, dt));
  EXPECT_EQ(t, 0.0);
  EXPECT_EQ(x, x0);
  EXPECT_EQ(dt, kNonFiniteShrink * 1e3);
  const Outcome o = integrate(s, m, x0, 0.0, 20.0, IntegrateOptions{.initial_step = 1e3});
  ASSERT_EQ(o.status, Status::finished);
  EXPECT_GE(o.rejected, 1);
  EXPECT_LT(test::distance(o.state, test::reference_solution(m, x0, 20.0, 1e-14)), 1e-8);
}

// With an attitude: the state and q against Fehlberg 7(8) with an attitude at 1e-13 over T = 20
// (both errors ~1e-11 here; bound 1e-9), the renormalisation of q within the tolerance's size, and
// the continuous extension of q at mid-step against the same reference.
TEST(Dop853, CarriesTheAttitude) {
  test::expect_carries_the_attitude([] { return Dop853Stepper(1e-12, 1e-12); });
}

TEST(Dop853, CommandLineNamesIt) { test::expect_command_line_runs("dop853"); }

}  // namespace
}  // namespace test_dop853
}  // namespace newtop
