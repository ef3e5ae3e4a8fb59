// Limits of the orbit model: ω0 → 0 at fixed λ is the fixed-centre Euler–Poisson model of
// docs/model.md §4 (newtop's own rhs and splitting), and a circular orbit is the e = 0 case of the
// elliptic one.

#include <gtest/gtest.h>

#include <cmath>

#include "newtop/integrate/splitting.hpp"
#include "newtop/model/model.hpp"
#include "orbit_problems.hpp"

namespace newtop {
namespace test_orbit_limits {
namespace {

using test::kOrbitEps;

constexpr double kLambda = 1.7;

QuadraticModel fixed_centre(const Body& body) {
  return QuadraticModel{body, QuadraticField::coulomb(0.0, kLambda)};
}

double distance_mg(const OrbitState& a, const State& b) {
  return std::max((a.m - b.m).cwiseAbs().maxCoeff(), (a.gamma - b.gamma).cwiseAbs().maxCoeff());
}

// The same formulas evaluated in another order: a few ε of the O(10) terms.
constexpr double kSameField = 32 * kOrbitEps;

TEST(OrbitLimits, ZeroRateIsTheFixedCentreVectorField) {
  const Body body = test::orbit_body();
  const CircularOrbitModel model(body, CircularOrbit::forced(0.0, kLambda));
  const OrbitState s = test::tumbling_state(body);
  const OrbitState f = rhs(model, s);
  const State g = rhs(fixed_centre(body), State{s.m, s.gamma});
  EXPECT_LT(distance_mg(f, g), kSameField);
  EXPECT_LT((f.normal - s.normal.cross(omega(body, s))).norm(), kSameField);
}

// At ω0 = 0 the orbit splitting and newtop's fixed-centre splitting are the same composition of
// the same exact sub-flows (the orbital rotation is the identity): they differ by round-off only,
// ~ε per sub-flow and step amplified by the flow over T = 5 (a factor < 100): 1e-12.
constexpr double kSameMethod = 1e-12;

TEST(OrbitLimits, ZeroRateSplittingIsTheFixedCentreSplitting) {
  const Body body = test::orbit_body();
  const CircularOrbitModel model(body, CircularOrbit::forced(0.0, kLambda));
  const OrbitState x0 = test::tumbling_state(body);
  for (const char* name : {"splitting2", "splitting4", "splitting6"}) {
    const OrbitSplittingStepper orbit(composition_table(name));
    SplittingStepper fixed(composition_table(name));
    OrbitState x = x0;
    State y{x0.m, x0.gamma};
    for (int i = 0; i < 500; ++i) {
      orbit.step(model, x, 0.01);
      fixed.step(fixed_centre(body), y, 0.01);
    }
    EXPECT_LT(distance_mg(x, y), kSameMethod) << name;
  }
}

// For small ω0 at fixed λ the orbital rotation is a perturbation of size ω0 T: the distance to the
// fixed-centre solution over T is linear in ω0, so halving ω0 halves it (ratio 2 up to the O(ω0)
// relative correction, here < 1%; allowance ±0.1).
constexpr double kLinearRatioSlack = 0.1;

TEST(OrbitLimits, DistanceToFixedCentreModelIsLinearInRate) {
  const Body body = test::orbit_body();
  const OrbitState x0 = test::tumbling_state(body);
  const double T = 3.0;
  const OrbitState ref = [&] {
    const CircularOrbitModel m0(body, CircularOrbit::forced(0.0, kLambda));
    return test::reference(m0, x0, 0.0, T);
  }();
  double previous = 0;
  for (double w0 : {4e-3, 2e-3, 1e-3}) {
    const CircularOrbitModel model(body, CircularOrbit::forced(w0, kLambda));
    const double d = test::max_distance(test::reference(model, x0, 0.0, T), ref);
    if (previous > 0) {
      EXPECT_NEAR(previous / d, 2.0, kLinearRatioSlack) << w0;
    }
    previous = d;
  }
  EXPECT_GT(previous, 1e-5);  // well above the reference's 1e-13: the ratio means something
}

// e = 0: ν = ω0 t, so d/dν = (1/ω0) d/dt exactly; the two right-hand sides agree to round-off.
TEST(OrbitLimits, CircularOrbitIsTheZeroEccentricityCase) {
  const Body body = test::orbit_body();
  const double w0 = 0.7;
  const CircularOrbitModel circular(body, CircularOrbit::from_rate(w0));
  const EllipticOrbitModel elliptic(body, EllipticOrbit::from_mean_motion(w0, 0.0, 0.4));
  const OrbitState s = test::tumbling_state(body);
  const OrbitState fc = rhs(circular, s);
  const OrbitState fe = rhs(elliptic, s, 1.234);
  const OrbitState scaled{fc.m / w0, fc.gamma / w0, fc.normal / w0};
  EXPECT_LT(test::max_distance(scaled, fe), kSameField);
  // Trajectories: references over Δν = 6 and Δt = 6/ω0 (Fehlberg 7(8) at 1e-14, ~1e-13 each).
  EXPECT_LT(test::max_distance(test::reference(elliptic, s, 0.4, 6.4),
                               test::reference(circular, s, 0.0, 6.0 / w0)),
            1e-11);
  // The splitting in ν with step h is the circular splitting with step h/ω0: the elapsed time of
  // each stage is its Δν/ω0 to round-off, so they agree to round-off over 600 steps.
  const OrbitSplittingStepper s4(composition_table("splitting4"));
  OrbitState x = s, y = s;
  for (int i = 0; i < 600; ++i) {
    s4.step(elliptic, x, 0.4 + 0.01 * i, 0.01);
    s4.step(circular, y, 0.01 / w0);
  }
  EXPECT_LT(test::max_distance(x, y), kSameMethod);
}

}  // namespace
}  // namespace test_orbit_limits
}  // namespace newtop
