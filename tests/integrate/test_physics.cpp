// Integrated motion against independent facts: two methods agreeing on a chaotic case, permanent
// rotations of docs/model.md §8 staying put, Brun's integral (docs/model.md §5), Casimirs over a
// million steps.

#include <gtest/gtest.h>

#include <cmath>

#include "support/problems.hpp"

namespace newtop {
namespace test_physics {
namespace {

using test::kEps;

// Splitting (order 8, h = 0.01: error ~ 1e-15 per unit time from the order test) and Fehlberg 7(8)
// at tolerance 1e-14 are independent methods; on a chaotic case over T = 10 their global errors,
// amplified by the local divergence of nearby orbits, must still agree to 1e-10 (the issue's
// bound).
constexpr double kAgreement = 1e-10;

TEST(Agreement, SplittingAndAdaptiveAgreeOnChaoticCase) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const State x0 = test::generic_state(m);
  const State ref = test::reference_solution(m, x0, 10.0, 1e-14);
  for (const char* name : {"splitting6", "splitting8"}) {
    SplittingStepper s(composition_table(name));
    const Outcome o = integrate(s, m, x0, 0.0, 10.0, IntegrateOptions{.step = 0.005});
    ASSERT_EQ(o.status, Status::finished);
    EXPECT_LT(test::distance(o.state, ref), kAgreement) << name;
  }
  // The case is not integrable and errors are not damped: a 1e-8 push grows (about 5× by T = 10).
  State pushed = x0;
  pushed.m.x() += 1e-8;
  EXPECT_GT(test::distance(test::reference_solution(m, pushed, 10.0, 1e-14), ref), 2e-8);
}

// Permanent rotations (docs/model.md §8) are equilibria of the equations, so every method keeps
// them up to its truncation error, which for splitting6 at h = 0.01 over T = 10 is ~1e-12; bound
// 1e-10.
constexpr double kStayPut = 1e-10;

void expect_stays_put(const QuadraticModel& m, const Vec3& w, const Vec3& gamma) {
  const State x0 = state_from_omega(m.body, w, gamma);
  const State d = rhs(m, x0);
  ASSERT_LT(std::max(d.m.norm(), d.gamma.norm()), 1e3 * kEps) << "not a permanent rotation";
  SplittingStepper s(composition_table("splitting6"));
  const Outcome o = integrate(s, m, x0, 0.0, 10.0, IntegrateOptions{.step = 0.01});
  EXPECT_LT(test::distance(o.state, x0), kStayPut);
}

TEST(PermanentRotations, AboutPrincipalAxisAtAnySpin) {
  const QuadraticModel m = test::brun_model();
  for (double W : {0.3, 1.7}) expect_stays_put(m, Vec3(0, 0, W), Vec3(0, 0, 1));
}

TEST(PermanentRotations, AnyAxisWhenOmegaSquaredIsLambda) {
  const QuadraticModel m{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                         QuadraticField::coulomb(0.0, 0.64)};
  const Vec3 n = Vec3(0.48, -0.6, 0.64);
  expect_stays_put(m, std::sqrt(0.64) * n, n);
  expect_stays_put(m, -std::sqrt(0.64) * n, n);
}

TEST(PermanentRotations, StaudeConeGeneratorWithCentreOfMass) {
  // r0 = a γ + b Iγ lies in the plane of γ and Iγ, so γ is a generator of the cone
  // γ·(Iγ × r0) = 0, and Ω² = λ + Mg (γ×r0)·(γ×Iγ)/|γ×Iγ|² = λ + M g b.
  const Vec3 I(1.0, 1.5, 2.2), gamma = Vec3(0.48, -0.6, 0.64);
  const double a = 0.2, b = 0.15, M = 1.0, g = 1.0, lambda = 0.5;
  const Vec3 r0 = a * gamma + b * I.cwiseProduct(gamma);
  const QuadraticModel m{Body::from_principal(I, M, r0), QuadraticField::coulomb(g, lambda)};
  const double Omega = std::sqrt(lambda + M * g * b);
  expect_stays_put(m, Omega * gamma, gamma);
}

// Brun's integral is conserved to the method's accuracy when r0 = 0 and visibly not otherwise.
TEST(BrunIntegral, ConservedOnlyWithoutCentreOfMassOffset) {
  const QuadraticModel brun = test::brun_model();
  ASSERT_TRUE(brun_holds(brun));
  const State x0 = test::generic_state(brun);
  SplittingStepper s(composition_table("splitting6"));
  double drift = 0;
  const double i0 = newtop::brun(brun, x0);
  integrate(s, brun, x0, 0.0, 50.0, IntegrateOptions{.step = 0.01}, [&](double, const State& x) {
    drift = std::max(drift, std::abs(newtop::brun(brun, x) - i0));
  });
  // splitting6 at h = 0.01: energy-like errors ~1e-13 of the integral's size O(1).
  EXPECT_LT(drift, 1e-10);

  // Brun's field from a plane not through O has a linear term M g r0·γ (g = −N d): no integral.
  const QuadraticModel off{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1)),
                           QuadraticField::brun(0.8, 0.5)};
  ASSERT_FALSE(brun_holds(off));
  ASSERT_EQ(conserved_integrals(off).size(), 3u);
  double change = 0;
  SplittingStepper s2(composition_table("splitting6"));
  integrate(s2, off, x0, 0.0, 50.0, IntegrateOptions{.step = 0.01}, [&](double, const State& x) {
    change = std::max(change, std::abs(newtop::brun(off, x) - i0));
  });
  EXPECT_GT(change, 1e-2);
}

// Casimirs over 1e6 steps. Each rotation adds to the state an increment formed without
// cancellation and rounded once; the roundings are unbiased, so γ·γ and m·γ follow a random walk
// of round-off, c·ε·√N with c = 8 (Brouwer's law). A biased rounding — e.g. cos θ − 1 formed as a
// difference, or an increment rounded twice the same way — drifts like N·ε/2 ≈ 1e-10 here.
TEST(LongRun, CasimirsOverAMillionSteps) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  State x = test::generic_state(m);
  const double g0 = geometric(x), a0 = area(x);
  SplittingStepper s(composition_table("splitting2"));
  constexpr int kSteps = 1'000'000;
  double e_first = 0, e_last = 0;
  const double e0 = energy(m, x);
  for (int i = 0; i < kSteps; ++i) {
    s.step(m, x, 0.02);
    if (i % 100 == 0) {
      const double de = std::abs(energy(m, x) - e0);
      if (i < kSteps / 10) e_first = std::max(e_first, de);
      if (i >= kSteps - kSteps / 10) e_last = std::max(e_last, de);
    }
  }
  const double bound = 8 * kEps * std::sqrt(double(kSteps));
  EXPECT_LT(std::abs(geometric(x) - g0), bound);
  EXPECT_LT(std::abs(area(x) - a0), bound * (1 + x.m.norm()));
  EXPECT_LT(e_last, 2.0 * e_first) << "energy error drifts";
}

TEST(Outcome, NonFiniteStateStopsAtOnce) {
  // RK4 with a step far beyond its stability limit on a fast spin overflows to inf/NaN.
  const QuadraticModel m = test::generic_model();
  const State x0 = state_from_omega(m.body, Vec3(1e3, -2e3, 5e2), Vec3(0.48, -0.6, 0.64));
  Rk4Stepper s;
  const Outcome o = integrate(s, m, x0, 0.0, 1e6, IntegrateOptions{.step = 10.0});
  EXPECT_EQ(o.status, Status::non_finite);
  EXPECT_TRUE(is_finite(o.state));
  EXPECT_LT(o.t, 1e6);
}

TEST(Outcome, StepLimit) {
  const QuadraticModel m = test::generic_model();
  SplittingStepper s(composition_table("splitting2"));
  const Outcome o = integrate(s, m, test::generic_state(m), 0.0, 1.0,
                              IntegrateOptions{.step = 0.01, .max_steps = 10});
  EXPECT_EQ(o.status, Status::step_limit);
  EXPECT_EQ(o.steps, 10);
}

TEST(Outcome, AdaptiveLandsExactlyOnEndTime) {
  const QuadraticModel m = test::generic_model();
  Dopri5Stepper s(1e-10, 1e-10);
  const Outcome o = integrate(s, m, test::generic_state(m), 0.0, 3.7, IntegrateOptions{});
  EXPECT_EQ(o.status, Status::finished);
  EXPECT_EQ(o.t, 3.7);
}

TEST(Outcome, AdaptiveUnderflowOnImpossibleTolerance) {
  // A tolerance below the round-off of the state cannot be met: the step shrinks to underflow.
  const QuadraticModel m = test::generic_model();
  Dopri5Stepper s(1e-30, 1e-30);
  const Outcome o =
      integrate(s, m, test::generic_state(m), 0.0, 1.0, IntegrateOptions{.max_steps = 1'000'000});
  EXPECT_EQ(o.status, Status::step_size_underflow);
}

}  // namespace
}  // namespace test_physics
}  // namespace newtop

namespace newtop {
namespace test_physics {
namespace {

// Dense output of Dormand–Prince: the continuous extension is of order 4, so at tolerance 1e-10
// its interpolation error inside a step is of the order of the step's error estimate, ~1e-10 per
// unit state; 1e-8 leaves a margin of 100 and still fails if calc_state returned the step's
// endpoint (off by ~h·|f| ~ 1e-2).
constexpr double kDenseAgreement = 1e-8;

TEST(DenseOutput, Dopri5InterpolatesInsideSteps) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const State x0 = test::generic_state(m);
  Dopri5Dense<QuadraticField> dense(m, 1e-10, 1e-10);
  dense.initialize(x0, 0.0, 0.01);
  int checked = 0;
  while (dense.current_time() < 3.0) {
    const auto [t_old, t_new] = dense.do_step();
    const double t_mid = 0.5 * (t_old + t_new);
    const State ref = test::reference_solution(m, x0, t_mid, 1e-14);
    EXPECT_LT(test::distance(dense.calc_state(t_mid), ref), kDenseAgreement) << "t = " << t_mid;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

}  // namespace
}  // namespace test_physics
}  // namespace newtop
