// The exact free-body flow as a splitting stepper (free body + potential kick): the conformance
// checks every stepper passes (concept, order, Casimirs, time symmetry, no energy drift, by the
// conformance suite's measure with its RK4 control), and
// exactness for the free body.

// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "newtop/integrate/free_body_flow.hpp"
#include "newtop/integrate/methods.hpp"
#include "newtop/model/integrals.hpp"
#include "support/energy_drift.hpp"

namespace newtop {
namespace test_free_body_flow {
namespace {

static_assert(FixedStepper<FreeBodySplittingStepper, QuadraticModel>);

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Observed order from errors at h, h/2, h/4 within ±0.2 of the nominal order (architecture.md).
constexpr double kOrderSlack = 0.2;
// Casimirs γ·γ and m·γ: each sub-flow preserves them up to rounding of a rotation or a cross
// product, a few ulps per step, accumulated as a random walk: 64 ε √N.
constexpr double kCasimirFactor = 64.0;
// Reference by Fehlberg 7(8) at tolerance 1e-14: global error ~1e-12, far below the splitting
// errors measured (≥ 1e-9 at the steps used).
constexpr double kReferenceTol = 1e-14;

QuadraticModel brun_model() {
  return QuadraticModel{Body::from_principal({1.0, 1.6, 2.1}, 1.0, Vec3::Zero()),
                        QuadraticField::coulomb(0.0, 2.0)};
}
QuadraticModel general_model() {
  return QuadraticModel{Body::from_principal({1.0, 1.6, 2.1}, 1.0, {0.1, -0.2, 0.3}),
                        QuadraticField::coulomb(1.0, 1.5)};
}
State start(const QuadraticModel& m) {
  return state_from_omega(m.body, {0.4, -0.7, 1.2}, Vec3(0.3, 0.5, 0.8).normalized());
}

State reference(const QuadraticModel& model, const State& x0, double t) {
  Fehlberg78Stepper s(kReferenceTol, kReferenceTol);
  return integrate(s, model, x0, 0.0, t, {}).state;
}

double error_at(const char* table, const QuadraticModel& model, double h, double t) {
  FreeBodySplittingStepper s(composition_table(table));
  const State x = integrate(s, model, start(model), 0.0, t, {.step = h}).state;
  const State r = reference(model, start(model), t);
  return std::max((x.m - r.m).norm(), (x.gamma - r.gamma).norm());
}

TEST(FreeBodyFlow, ExactForTheFreeBodyWithOneLargeStep) {
  // A free body: the splitting is the exact flow, whatever the step.
  const QuadraticModel model{Body::from_principal({1.0, 1.6, 2.1}, 1.0, Vec3::Zero()),
                             QuadraticField{}};
  const State x0 = start(model);
  const double t = 7.3;
  FreeBodySplittingStepper s(composition_table("splitting2"));
  const State x = integrate(s, model, x0, 0.0, t, {.step = t}).state;
  const State r = reference(model, x0, t);
  // rkf78's own global error, ~1e-12, with a factor 10 of margin.
  constexpr double kExact = 1e-11;
  EXPECT_LT((x.m - r.m).norm(), kExact);
  EXPECT_LT((x.gamma - r.gamma).norm(), kExact);
}

struct OrderCase {
  const char* table;
  int order;
  double h;
};

class FreeBodyOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(FreeBodyOrder, ObservedOrderMatchesNominal) {
  const auto [table, order, h] = GetParam();
  const QuadraticModel model = general_model();
  const double t = 2.0;
  const double e1 = error_at(table, model, h, t), e2 = error_at(table, model, h / 2, t),
               e4 = error_at(table, model, h / 4, t);
  ASSERT_TRUE(std::isfinite(e1) && std::isfinite(e4));
  EXPECT_NEAR(std::log2(e1 / e2), order, kOrderSlack) << e1 << " " << e2;
  EXPECT_NEAR(std::log2(e2 / e4), order, kOrderSlack) << e2 << " " << e4;
  EXPECT_EQ(FreeBodySplittingStepper(composition_table(table)).order(), order);
}

INSTANTIATE_TEST_SUITE_P(Tables, FreeBodyOrder,
                         ::testing::Values(OrderCase{"splitting2", 2, 0.05},
                                           OrderCase{"splitting4", 4, 0.2}));

TEST(FreeBodyFlow, PreservesCasimirs) {
  const QuadraticModel model = brun_model();
  const State x0 = start(model);
  FreeBodySplittingStepper s(composition_table("splitting4"));
  const int n = 2000;
  double max_casimir = 0.0;
  integrate(s, model, x0, 0.0, 100.0, {.step = 0.05}, [&](double, const State& x) {
    max_casimir = std::max(
        {max_casimir, std::abs(geometric(x) - 1.0), std::abs(area(x) - area(x0)) / x0.m.norm()});
  });
  EXPECT_LT(max_casimir, kCasimirFactor * kEps * std::sqrt(double(n)));
}

// The conformance suite's drift measure (tests/support/energy_drift.hpp), over as many steps.
constexpr int kDriftSteps = 50000;
constexpr double kDriftStep = 0.05;

TEST(FreeBodyFlow, EnergyErrorBoundedWithoutDrift) {
  const QuadraticModel model = brun_model();
  const test::EnergyErrorProfile p =
      test::energy_error_profile(FreeBodySplittingStepper(composition_table("splitting4")), model,
                                 start(model), kDriftStep, kDriftSteps);
  EXPECT_GT(p.first, 0.0);
  EXPECT_TRUE(test::without_drift(p)) << "first tenth " << p.first << ", last tenth " << p.last;
}

// The same measure on the same problem must see the drift of a non-symplectic method, or it
// proves nothing.
TEST(FreeBodyFlow, DriftMeasureDetectsRk4Drift) {
  const QuadraticModel model = brun_model();
  const test::EnergyErrorProfile p =
      test::energy_error_profile(Rk4Stepper(), model, start(model), kDriftStep, kDriftSteps);
  EXPECT_FALSE(test::without_drift(p)) << "first tenth " << p.first << ", last tenth " << p.last;
}

TEST(FreeBodyFlow, StepForwardThenBackReturnsToStart) {
  const QuadraticModel model = general_model();
  const State x0 = start(model);
  FreeBodySplittingStepper s(composition_table("splitting4"));
  State x = x0;
  s.step(model, x, 0.1);
  EXPECT_GT((x.m - x0.m).norm(), 1e-3);  // the step moved the state
  s.step(model, x, -0.1);
  // A few ulps per sub-flow; the quadrature of the precession angle adds its own few ulps.
  constexpr double kSymmetry = 1e-13;
  EXPECT_LT((x.m - x0.m).norm(), kSymmetry);
  EXPECT_LT((x.gamma - x0.gamma).norm(), kSymmetry);
}

}  // namespace
}  // namespace test_free_body_flow
}  // namespace newtop
