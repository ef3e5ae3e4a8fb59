// Dense output: the Hermite interpolant against polynomials and its error formula, the order of
// each adaptive method's continuous extension inside a step, output at requested times against an
// independent tight reference, and the output times themselves.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "support/problems.hpp"

namespace newtop {
namespace test_dense_output {
namespace {

using test::kEps;
using Point = HermiteInterpolant::Point;

// ---- Hermite interpolation --------------------------------------------------------------------

/// p(θ) = Σ_j c_j θ^j in component k, with coefficients c_j = (j + 1 + k) / 8 · (−1)^j.
double poly(int degree, int k, double theta, bool derivative) {
  double v = 0;
  for (int j = 0; j <= degree; ++j) {
    const double c = (j + 1 + k) / 8.0 * (j % 2 ? -1.0 : 1.0);
    v += derivative ? (j == 0 ? 0.0 : c * j * std::pow(theta, j - 1)) : c * std::pow(theta, j);
  }
  return v;
}

HermiteInterpolant interpolant_of(int degree, const std::array<double, 4>& theta) {
  std::array<Point, 4> y{}, dy{};
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 6; ++k) {
      y[i][k] = poly(degree, k, theta[i], false);
      dy[i][k] = poly(degree, k, theta[i], true);
    }
  }
  return HermiteInterpolant(theta, y, dy);
}

constexpr std::array<double, 4> kNodes{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};

// Values of size ≤ Σ|c_j| ≈ 8 through a Newton form of 8 terms with divided differences over gaps
// of 1/3: a few hundred ε of round-off.
constexpr double kPolynomialRoundoff = 512 * kEps;

TEST(Hermite, ReproducesPolynomialsOfDegreeSeven) {
  for (int degree : {0, 3, 7}) {
    const HermiteInterpolant u = interpolant_of(degree, kNodes);
    for (double theta = 0.0; theta <= 1.0; theta += 0.05) {
      const Point v = u(theta);
      for (int k = 0; k < 6; ++k) {
        EXPECT_NEAR(v[k], poly(degree, k, theta, false), kPolynomialRoundoff) << degree;
      }
    }
  }
}

TEST(Hermite, ErrorOfDegreeEightIsTheNodePolynomialSquared) {
  // For y = θ^8 the interpolation error y − u is y^(8)/8! Π(θ − θ_i)² = Π(θ − θ_i)² exactly.
  std::array<Point, 4> y{}, dy{};
  for (int i = 0; i < 4; ++i) {
    y[i].fill(std::pow(kNodes[i], 8));
    dy[i].fill(8 * std::pow(kNodes[i], 7));
  }
  const HermiteInterpolant u(kNodes, y, dy);
  for (double theta : {0.1, 0.25, 0.5, 0.8, 0.95}) {
    double w = 1;
    for (double t : kNodes) w *= (theta - t) * (theta - t);
    EXPECT_NEAR(std::pow(theta, 8) - u(theta)[0], w, kPolynomialRoundoff);
    EXPECT_GT(w, 1e-7);  // the error is far above round-off: the check has teeth
  }
}

// ---- Continuous extension inside one step -------------------------------------------------

/// Error of the continuous extension at the middle of one accepted step of size h from x0.
template <class S>
double midpoint_error(S& s, const QuadraticModel& m, const State& x0, double h) {
  State x = x0;
  double t = 0.0, dt = h;
  EXPECT_TRUE(s.try_step(m, x, t, dt)) << "step of " << h << " rejected";
  EXPECT_EQ(t, h);
  const State ref = test::reference_solution(m, x0, 0.5 * h, 1e-14);
  return test::distance(s.dense_state(m, 0.5 * h), ref);
}

// Observed order of the interpolation error between h and h/2, within 0.5 of the nominal order
// of the error: Fehlberg's degree-7 Hermite interpolant has error O(h^8), Dormand–Prince 5(4)'s
// continuous extension (order 4) O(h^5), Dormand–Prince 8(5,3)'s (order 7) O(h^8). Steps chosen
// where the error is far above the reference's ~1e-15 and in the asymptotic regime.
struct OrderCase {
  const char* name;
  double h;
  double nominal;
};

TEST(ContinuousExtension, ObservedOrderInsideAStep) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const State x0 = test::generic_state(m);
  for (const OrderCase& c : {OrderCase{"rkf78", 0.8, 8.0}, OrderCase{"dopri5", 0.2, 5.0},
                             OrderCase{"dop853", 0.8, 8.0}}) {
    // A tolerance of 1 accepts any of these steps: the order is that of the formula, not of
    // the controller.
    auto err = [&](double h) {
      if (std::string(c.name) == "rkf78") {
        Fehlberg78Stepper s(1.0, 1.0);
        return midpoint_error(s, m, x0, h);
      }
      if (std::string(c.name) == "dop853") {
        Dop853Stepper s(1.0, 1.0);
        return midpoint_error(s, m, x0, h);
      }
      Dopri5Stepper s(1.0, 1.0);
      return midpoint_error(s, m, x0, h);
    };
    const double e1 = err(c.h), e2 = err(c.h / 2);
    ASSERT_GT(e2, 1e-13) << c.name << ": error at round-off, the order is not observable";
    const double p = std::log2(e1 / e2);
    EXPECT_NEAR(p, c.nominal, 0.5) << c.name << " errors " << e1 << ", " << e2;
  }
}

// ---- Output at requested times against an independent reference ---------------------------

/// The reference at the given times: splitting8 at h ≤ 0.005 landing on every time (error ~1e-15
/// per unit time, test_physics), no interpolation involved.
std::vector<State> reference_at(const QuadraticModel& m, const State& x0, const OutputTimes& times,
                                double T) {
  std::vector<State> ref(static_cast<std::size_t>(times.size()));
  SplittingStepper s(composition_table("splitting8"));
  integrate_sampled(s, m, x0, 0.0, T, times, IntegrateOptions{.step = 0.005},
                    [&](std::int64_t k, double, const State& x) { ref[k] = x; });
  return ref;
}

// The state at an output time carries the global error of the step's start plus one step's
// interpolation error, which the degree of the interpolants keeps at the size of the local error:
// the error at output times must stay below twice the largest error at the accepted steps' ends
// plus the tolerance. Linear interpolation instead would be off by ~h² |x''| / 8 ~ 1e-3.
constexpr double kEndErrorFactor = 2.0;
// Dormand–Prince 8(5,3)'s continuous extension is of order 7, one below its step: inside a step of
// h its error is about 1/h times the step's local error (h ≈ 0.2 at this tolerance: 5×; measured
// 7× the largest error at the ends), so the bound for it is 20 e_end + tol — still 10⁵ below what
// linear interpolation would give.
constexpr double kEndErrorFactorOrder7 = 20.0;

TEST(OutputTimes, AdaptiveSamplesAgreeWithReferenceAsWellAsStepEnds) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const State x0 = test::generic_state(m);
  constexpr double T = 10.0, kTol = 1e-10;
  const OutputTimes every = OutputTimes::every(0.05, 0.0, T);
  const std::vector<State> ref = reference_at(m, x0, every, T);
  for (const char* name : {"rkf78", "dopri5", "dop853", "taylor"}) {
    std::vector<double> step_t;
    std::vector<State> step_x, sample_x(ref.size());
    const MethodSettings settings{name, 0.0, kTol, kTol, std::nullopt};
    const Outcome o = run_method_sampled(
        settings, m, x0, 0.0, T, every, {},
        [&](std::int64_t k, double t, const State& x) {
          EXPECT_EQ(t, every[k]);
          sample_x[k] = x;
        },
        [&](double t, const State& x) {
          if (t > 0.0 && t < T) step_t.push_back(t), step_x.push_back(x);
        });
    ASSERT_EQ(o.status, Status::finished);
    // Output times on a step's end would not exercise the interpolant.
    std::set<double> output;
    for (std::int64_t k = 0; k < every.size(); ++k) output.insert(every[k]);
    EXPECT_EQ(
        std::count_if(step_t.begin(), step_t.end(), [&](double t) { return output.count(t); }), 0)
        << name;
    const std::vector<State> ref_steps = reference_at(m, x0, OutputTimes::list(step_t, 0.0, T), T);
    double e_end = 0, e_out = 0;
    for (std::size_t i = 0; i < step_x.size(); ++i) {
      e_end = std::max(e_end, test::distance(step_x[i], ref_steps[i]));
    }
    for (std::size_t k = 0; k < ref.size(); ++k) {
      e_out = std::max(e_out, test::distance(sample_x[k], ref[k]));
    }
    const double factor = std::string(name) == "dop853" ? kEndErrorFactorOrder7 : kEndErrorFactor;
    EXPECT_LT(e_out, factor * e_end + kTol) << name << " step ends " << e_end;
    EXPECT_GT(e_end, 0.0);
  }
}

TEST(OutputTimes, FixedStepMethodsLandOnEveryOutputTime) {
  const QuadraticModel m = test::generic_model();
  const State x0 = test::generic_state(m);
  SplittingStepper s(composition_table("splitting6"));
  const OutputTimes every = OutputTimes::every(0.1, 0.0, 1.0);
  std::vector<State> sampled;
  const Outcome o = integrate_sampled(s, m, x0, 0.0, 1.0, every, IntegrateOptions{.step = 0.03},
                                      [&](std::int64_t k, double t, const State& x) {
                                        EXPECT_EQ(t, 0.1 * static_cast<double>(k));
                                        sampled.push_back(x);
                                      });
  ASSERT_EQ(o.status, Status::finished);
  EXPECT_EQ(o.steps, 40);  // 0.1 / ceil(0.1 / 0.03) = 0.025
  ASSERT_EQ(sampled.size(), 11u);
  // The same as a plain run at the step 0.025 to each output time, up to the rounding of the
  // segments' steps (a few ε per step over 40 steps).
  for (std::size_t k = 1; k < sampled.size(); ++k) {
    SplittingStepper plain(composition_table("splitting6"));
    const double tk = 0.1 * static_cast<double>(k);
    const State x = integrate(plain, m, x0, 0.0, tk, IntegrateOptions{.step = 0.025}).state;
    EXPECT_LT(test::distance(x, sampled[k]), 64 * kEps) << tk;
  }
}

TEST(OutputTimes, EqualIntervalsWithoutAccumulation) {
  const OutputTimes a = OutputTimes::every(0.1, 0.0, 0.3);
  ASSERT_EQ(a.size(), 4);
  EXPECT_EQ(a[3], 0.3);  // 3 · 0.1 = 0.30000000000000004 is the end time 0.3, rounded
  const OutputTimes b = OutputTimes::every(0.1, 0.0, 0.25);
  ASSERT_EQ(b.size(), 3);
  EXPECT_EQ(b[2], 0.2);
  const OutputTimes c = OutputTimes::every(0.1, 0.0, 100.0);
  ASSERT_EQ(c.size(), 1001);
  for (std::int64_t k = 0; k < c.size(); ++k) EXPECT_EQ(c[k], 0.1 * static_cast<double>(k));
  const OutputTimes back = OutputTimes::every(0.5, 10.0, 8.0);
  ASSERT_EQ(back.size(), 5);
  EXPECT_EQ(back[1], 9.5);
  EXPECT_EQ(back[4], 8.0);
  for (double D : {0.0, -0.1, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(OutputTimes::every(D, 0.0, 1.0), InputError) << D;
  }
  EXPECT_THROW(OutputTimes::every(1e-300, 0.0, 1.0), InputError);       // 1e300 output times
  EXPECT_THROW(OutputTimes::every(1e-12, 1e6, 1e6 + 1.0), InputError);  // below the times' ulp
  EXPECT_EQ(OutputTimes::list({0.5, 1.0}, 0.0, 1.0).size(), 2);
  EXPECT_EQ(OutputTimes::list({2.0, 1.5}, 3.0, 1.0)[1], 1.5);
  EXPECT_THROW(OutputTimes::list({0.5, 1.5}, 0.0, 1.0), InputError);
  EXPECT_THROW(OutputTimes::list({0.5, 0.5}, 0.0, 1.0), InputError);
  EXPECT_THROW(OutputTimes::list({1.5, 2.0}, 3.0, 1.0), InputError);
}

}  // namespace
}  // namespace test_dense_output
}  // namespace newtop
