// One typed conformance suite over every stepper (a new stepper joins with one line in Steppers):
// observed order, Casimirs, time symmetry and bounded energy error for the Poisson integrators.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "newtop/integrate/free_body_flow.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_conformance {
namespace {

using test::kEps;
namespace ode = boost::numeric::odeint;

// H0 is the largest step in hundredths and Span the length of the order test: integers, because
// clang 14 has no floating-point non-type template parameters (n / 100.0 is the double nearest
// n/100, the same as the decimal literal).
template <const char* Name, int Order, int H0, int Span = 2>
struct Splitting {
  static SplittingStepper make() { return SplittingStepper(composition_table(Name)); }
  static constexpr int order = Order;
  static constexpr bool poisson = true;     // exact sub-flows: Casimirs, symmetry, bounded energy
  static constexpr bool gyrostat = true;    // handles k ≠ 0
  static constexpr double h0 = H0 / 100.0;  // largest step of the order test (asymptotic regime)
  static constexpr double T = Span;         // length of the order test
  static constexpr bool round_off_drifts = false;
};

// The same tables with the spin split of the free body (|m|² flow exact, two axis rotations).
template <const char* Name, int Order, int H0, int Span = 2>
struct SpinSplitting {
  static SplittingStepper make() {
    const CompositionTable& t = composition_table(Name);
    SplitOrdering o = default_ordering(t);
    o.free_body = FreeBodySplit::spin;
    return SplittingStepper(t, o);
  }
  static constexpr int order = Order;
  static constexpr bool poisson = true;
  static constexpr bool gyrostat = true;
  static constexpr double h0 = H0 / 100.0;
  static constexpr double T = Span;
  static constexpr bool round_off_drifts = false;
};

// The exact free-body flow (Euler–Poinsot) plus the kick, composed by the same tables or by the
// near-integrable tables (whose order for a potential of order one is their generic order); it
// needs k = 0, so it runs on the gyrostat-free variant of the test model.
template <const char* Name, int Order, int H0, int Span = 2>
struct FreeBodySplitting {
  static FreeBodySplittingStepper make() {
    return FreeBodySplittingStepper(composition_table(Name));
  }
  static constexpr int order = Order;
  static constexpr bool poisson = true;
  static constexpr bool gyrostat = false;
  static constexpr double h0 = H0 / 100.0;
  static constexpr double T = Span;
  static constexpr bool round_off_drifts = true;  // see CasimirsToRoundOff
};

template <class S, int Order, int H0, int Span = 2>
struct RungeKutta {
  static S make() { return S(); }
  static constexpr int order = Order;
  static constexpr bool poisson = false;
  static constexpr bool gyrostat = true;
  static constexpr double h0 = H0 / 100.0;
  static constexpr double T = Span;
  static constexpr bool round_off_drifts = false;
};

constexpr char kS2[] = "splitting2", kS4[] = "splitting4", kS4y[] = "splitting4-yoshida",
               kS6[] = "splitting6", kS8[] = "splitting8", kS8m[] = "splitting8-mclachlan",
               kSbab3[] = "sbab3", kSaba3[] = "saba3", kAba864[] = "aba864", kAba1064[] = "aba1064";

using Steppers = ::testing::Types<
    Splitting<kS2, 2, 2>, Splitting<kS4, 4, 10>, Splitting<kS4y, 4, 5>, Splitting<kS6, 6, 20>,
    Splitting<kS8, 8, 40, 6>, Splitting<kS8m, 8, 40>, RungeKutta<Rk4Stepper, 4, 5>,
    RungeKutta<OdeintFixedStepper<ode::runge_kutta_dopri5<OdeState>, 5>, 5, 10, 10>,
    RungeKutta<OdeintFixedStepper<ode::runge_kutta_fehlberg78<OdeState>, 8>, 8, 50, 10>,
    FreeBodySplitting<kS4, 4, 10>, SpinSplitting<kS2, 2, 2>, SpinSplitting<kS4, 4, 10>,
    SpinSplitting<kS6, 6, 20>, SpinSplitting<kS8, 8, 50>, FreeBodySplitting<kSbab3, 2, 2>,
    FreeBodySplitting<kSaba3, 2, 2>, FreeBodySplitting<kAba864, 4, 10>,
    FreeBodySplitting<kAba1064, 4, 10>>;

template <class T>
class Conformance : public ::testing::Test {};

template <class T>
QuadraticModel conformance_model() {
  return test::generic_model(T::gyrostat ? Vec3(0.1, -0.2, 0.05) : Vec3::Zero());
}
TYPED_TEST_SUITE(Conformance, Steppers);

TYPED_TEST(Conformance, SatisfiesTheStepperConcept) {
  static_assert(FixedStepper<decltype(TypeParam::make()), QuadraticModel>);
  EXPECT_EQ(TypeParam::make().order(), TypeParam::order);
}

// Observed order: errors at h, h/2, h/4 against a Fehlberg 7(8) solution at tolerance 1e-15
// (accurate to ~4e-15). The order is the least-squares slope of log e against log h over the three
// points, log2(e(h)/e(h/4))/2, which averages out the sign changes of the leading error term that
// make a single pair jitter; it must be within ±0.2 of the nominal order. The smallest error must
// stay above 5e-14 (12× the reference's error, biasing the slope by < 0.06).
constexpr double kOrderSlack = 0.2;
constexpr double kErrorFloor = 5e-14;

TYPED_TEST(Conformance, ObservedOrder) {
  const QuadraticModel m = conformance_model<TypeParam>();
  const State x0 = test::generic_state(m);
  const State ref = test::reference_solution(m, x0, TypeParam::T, 1e-15);
  std::vector<double> err;
  for (double h : {TypeParam::h0, TypeParam::h0 / 2, TypeParam::h0 / 4}) {
    auto s = TypeParam::make();
    const Outcome o = integrate(s, m, x0, 0.0, TypeParam::T, IntegrateOptions{.step = h});
    ASSERT_EQ(o.status, Status::finished);
    err.push_back(test::distance(o.state, ref));
  }
  ASSERT_GT(err[2], kErrorFloor) << "h0 too small: errors reach the reference's accuracy";
  const double p = std::log2(err[0] / err[2]) / 2;
  EXPECT_NEAR(p, TypeParam::order, kOrderSlack)
      << "errors " << err[0] << " " << err[1] << " " << err[2];
}

// Casimirs γ·γ and m·γ: every sub-flow preserves them exactly, so only round-off remains; each
// sub-flow's increment is rounded once and without bias, so it is a random walk: c·ε·√N with c = 8
// covering the per-step rounding of the increments.
constexpr int kCasimirSteps = 20000;

TYPED_TEST(Conformance, CasimirsToRoundOff) {
  if (!TypeParam::poisson) GTEST_SKIP() << "not a Poisson integrator";
  const QuadraticModel m = conformance_model<TypeParam>();
  State x = test::generic_state(m);
  const double g0 = geometric(x), a0 = area(x);
  auto s = TypeParam::make();
  double dg = 0, da = 0;
  for (int i = 0; i < kCasimirSteps; ++i) {
    s.step(m, x, 0.05);
    dg = std::max(dg, std::abs(geometric(x) - g0));
    da = std::max(da, std::abs(area(x) - a0));
  }
  // The exact free-body flow recomputes the state from the elliptic functions each call: its
  // rounding keeps its sign while the state changes slowly, and m·γ drifts by about 0.15 ε per
  // step (measured over 2e4 … 8e4 steps, growing like N). Known defect, bounded at 0.5 ε per step.
  const double bound = TypeParam::round_off_drifts ? 0.5 * kEps * kCasimirSteps
                                                   : 8 * kEps * std::sqrt(double(kCasimirSteps));
  EXPECT_LT(dg, bound * g0);
  EXPECT_LT(da, bound * (x.m.norm() + std::abs(a0)));
}

// Time symmetry: a step of h then −h returns to the start. Each of the s sub-flows rounds once
// (relative ε on increments of size ~h|x|), so the return error is ~ s·ε·|x|.
TYPED_TEST(Conformance, SymmetricMethodsReturnOnNegativeStep) {
  if constexpr (!TypeParam::poisson) {
    GTEST_SKIP() << "Runge–Kutta methods here are not symmetric";
  } else {
    const QuadraticModel m = conformance_model<TypeParam>();
    const State x0 = test::generic_state(m);
    auto s = TypeParam::make();
    State x = x0;
    s.step(m, x, 0.1);
    ASSERT_GT(test::distance(x, x0), 1e-3);  // it did move
    s.step(m, x, -0.1);
    const double scale = std::max(x0.m.norm(), 1.0);
    EXPECT_LT(test::distance(x, x0), 4.0 * double(s.stages()) * kEps * scale);
  }
}

// Bounded energy error without drift: the maximum energy error over the last tenth of a long run
// is no larger than twice that over the first tenth (a linear drift makes it ~9× larger; the
// factor 2 allows the quasi-periodic oscillation of the modified energy to reach a new maximum).
// The step is each method's h0, where its truncation error stands well above round-off (at a
// smaller step an eighth-order method's energy error is its round-off, which grows like √N by
// Brouwer's law and says nothing of the method).
constexpr int kEnergySteps = 50000;

template <class S>
void energy_error_profile(S s, const QuadraticModel& m, double h, double& first, double& last) {
  State x = test::generic_state(m);
  const double e0 = energy(m, x);
  first = last = 0;
  for (int i = 0; i < kEnergySteps; ++i) {
    s.step(m, x, h);
    const double de = std::abs(energy(m, x) - e0);
    if (i < kEnergySteps / 10) first = std::max(first, de);
    if (i >= kEnergySteps - kEnergySteps / 10) last = std::max(last, de);
  }
}

TYPED_TEST(Conformance, EnergyErrorBoundedWithoutDrift) {
  if (!TypeParam::poisson) GTEST_SKIP() << "not symplectic";
  const QuadraticModel m = conformance_model<TypeParam>();
  double first, last;
  energy_error_profile(TypeParam::make(), m, TypeParam::h0, first, last);
  EXPECT_LT(last, 2.0 * first + 64 * kEps) << "first tenth " << first << ", last tenth " << last;
}

// The same measure must see the drift of a non-symplectic method, or it proves nothing.
TEST(ConformanceControl, Rk4EnergyDriftIsDetected) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  double first, last;
  energy_error_profile(Rk4Stepper(), m, 0.05, first, last);
  EXPECT_GT(last, 2.0 * first);
}

}  // namespace
}  // namespace test_conformance
}  // namespace newtop
