// The driver's contract: the first adaptive step comes from the problem, a non-finite trial is a
// rejected step, runs that could never happen are bad input, and the outcome's time is the time of
// its state.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "support/problems.hpp"

namespace newtop {
namespace test_driver {
namespace {

/// The scenario of examples/lagrange_like.toml: a fast symmetric top (r = 4) whose first trial step
/// of span/1000 = 10 at T = 1e4 overflowed.
QuadraticModel lagrange_like() {
  return QuadraticModel{Body::from_principal(Vec3(3.0, 3.0, 1.2), 2.0, Vec3(0, 0, 0.4)),
                        QuadraticField::from_g_R(1.0, 6.0)};
}
State lagrange_like_state(const QuadraticModel& m) {
  return state_from_omega(m.body, Vec3(0.2, -0.1, 4.0), Vec3(0.6, 0.0, 0.8));
}

TEST(FirstStep, EstimatedFromTheProblemNotFromTheSpan) {
  const QuadraticModel m = lagrange_like();
  const State x0 = lagrange_like_state(m);
  Fehlberg78Stepper s(1e-12, 1e-12);
  const double h_short = s.initial_step(m, x0, 0.0, 10.0);
  const double h_long = s.initial_step(m, x0, 0.0, 1e4);
  EXPECT_EQ(h_short, h_long);
  // The fastest motion turns γ at |ω| ≈ 4 rad per unit time; an 8th-order step at 1e-12 resolves
  // a fraction of a radian: the estimate must lie well below 1/|ω|, and above round-off.
  EXPECT_GT(h_long, 1e-6);
  EXPECT_LT(h_long, 0.25);
  // Never beyond the span; backward, the same up to the second-derivative estimate, which the
  // Euler step then takes backward (a relative change of order h |f''| / |f'| ~ 1e-2).
  EXPECT_LE(s.initial_step(m, x0, 0.0, 1e-9), 1e-9);
  EXPECT_NEAR(s.initial_step(m, x0, 0.0, -1e4), h_long, 0.05 * h_long);
}

// Energy and Lagrange's integral m3 over T = 1e4 at tolerance 1e-12: the error per step is
// ~1e-12 of O(10) values and grows at most linearly over ~1e5 steps: 1e-6 leaves a margin of
// ~100 and still fails for a run that went astray.
constexpr double kLongRunDrift = 1e-6;

TEST(AdaptiveDriver, LongRunsFinish) {
  const QuadraticModel m = lagrange_like();
  const State x0 = lagrange_like_state(m);
  for (const char* name : {"rkf78", "dopri5", "dop853", "taylor"}) {
    const MethodSettings settings{name, 0.0, 1e-12, 1e-12, std::nullopt};
    double drift = 0;
    const double e0 = energy(m, x0), l0 = lagrange(m, x0);
    const Outcome o = run_method(settings, m, x0, 0.0, 1e4, {}, [&](double, const State& x) {
      drift = std::max({drift, std::abs(energy(m, x) - e0), std::abs(lagrange(m, x) - l0)});
    });
    ASSERT_EQ(o.status, Status::finished) << name << " at t = " << o.t;
    EXPECT_EQ(o.t, 1e4);
    EXPECT_LT(drift, kLongRunDrift) << name;
  }
}

TEST(AdaptiveDriver, NonFiniteTrialIsARejectedStep) {
  // A first trial of 10 time units overflows to NaN; the run shrinks it and goes on.
  const QuadraticModel m = lagrange_like();
  const State x0 = lagrange_like_state(m);
  Fehlberg78Stepper s(1e-12, 1e-12);
  const Outcome o = integrate(s, m, x0, 0.0, 100.0, IntegrateOptions{.initial_step = 10.0});
  ASSERT_EQ(o.status, Status::finished) << "at t = " << o.t;
  EXPECT_GE(o.rejected, 1);
  EXPECT_LT(test::distance(o.state, test::reference_solution(m, x0, 100.0, 1e-13)), 1e-8);
}

/// A stepper that accepts a non-finite trial whenever dt > 1 (as a controller that tests err > 1
/// does with an error estimate of NaN) and takes exact steps of the motion x' = 0 otherwise.
struct AcceptsNaN {
  int order() const { return 1; }
  template <class M>
  double initial_step(const M&, const State&, double, double) const {
    return 100.0;
  }
  template <class M>
  bool try_step(const M&, State& x, double& t, double& dt) const {
    if (dt > 1) x.m.x() = std::numeric_limits<double>::quiet_NaN();
    t += dt;
    return true;
  }
};

TEST(AdaptiveDriver, DriverRejectsNonFiniteTrialsOfAnyStepper) {
  const QuadraticModel m = test::generic_model();
  const State x0 = test::generic_state(m);
  AcceptsNaN s;
  const Outcome o = integrate(s, m, x0, 0.0, 10.0, IntegrateOptions{});
  ASSERT_EQ(o.status, Status::finished);
  EXPECT_EQ(o.state, x0);
  // 100, cut to the span 10 → 2 → 0.4: two rejections, then steps of 0.4 land on 10.
  EXPECT_EQ(o.rejected, 2);
  EXPECT_EQ(o.steps, 25);
}

TEST(Driver, RunsThatCannotHappenAreBadInput) {
  const QuadraticModel m = test::brun_model();
  const State x0 = test::generic_state(m);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double h : {0.0, -0.01, nan, inf}) {
    SplittingStepper s(composition_table("splitting2"));
    EXPECT_THROW(integrate(s, m, x0, 0.0, 1.0, IntegrateOptions{.step = h}), InputError) << h;
  }
  for (double t1 : {nan, inf, -inf}) {
    SplittingStepper s(composition_table("splitting2"));
    EXPECT_THROW(integrate(s, m, x0, 0.0, t1, IntegrateOptions{.step = 0.1}), InputError) << t1;
    Dopri5Stepper a(1e-8, 1e-8);
    EXPECT_THROW(integrate(a, m, x0, 0.0, t1, IntegrateOptions{}), InputError) << t1;
  }
  State bad = x0;
  bad.gamma.z() = nan;
  Dopri5Stepper a(1e-8, 1e-8);
  EXPECT_THROW(integrate(a, m, bad, 0.0, 1.0, IntegrateOptions{}), InputError);
  // 1e7 / 1e-12 = 1e19 steps: more than an int64 (and than 2^53) can count.
  SplittingStepper s(composition_table("splitting2"));
  try {
    integrate(s, m, x0, 0.0, 1e7, IntegrateOptions{.step = 1e-12});
    ADD_FAILURE() << "no error for 1e19 steps";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1e+19"), std::string::npos) << e.what();
  }
  EXPECT_THROW(fixed_step_count(0.0, 1e300, 0.01), InputError);
  EXPECT_EQ(fixed_step_count(0.0, 1.0, 0.3), 4);
  EXPECT_EQ(fixed_step_count(0.0, -1.0, 0.5), 2);
}

TEST(Driver, OutcomeTimeIsTheTimeOfItsState) {
  // RK4 with a step far beyond its stability limit on a fast spin overflows to inf/NaN: the
  // outcome holds the last finite state and its own time, steps × h.
  const QuadraticModel m = test::generic_model();
  const State x0 = state_from_omega(m.body, Vec3(1e3, -2e3, 5e2), Vec3(0.48, -0.6, 0.64));
  Rk4Stepper s;
  const Outcome o = integrate(s, m, x0, 0.0, 1e6, IntegrateOptions{.step = 10.0});
  ASSERT_EQ(o.status, Status::non_finite);
  EXPECT_EQ(o.t, 10.0 * static_cast<double>(o.steps));
  Rk4Stepper again;
  const Outcome o2 = integrate(again, m, x0, 0.0, o.t, IntegrateOptions{.step = 10.0});
  EXPECT_EQ(o2.state, o.state);
}

}  // namespace
}  // namespace test_driver
}  // namespace newtop
