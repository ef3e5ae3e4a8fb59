// Taylor's method on the orbit models (newtop/orbit/orbit_taylor.hpp) against what does not share
// its recurrences: the right-hand side of orbit_model.cpp and its derivative by central
// differences (the first two coefficients), Fehlberg 7(8) near round-off (runs on a circle and an
// ellipse), the Jacobi integral of a circular orbit, the ellipse of eccentricity 0 against the
// circle, and the section and sampled output of dop853.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "newtop/integrate/taylor.hpp"
#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_section.hpp"
#include "newtop/orbit/orbit_stability.hpp"
#include "newtop/orbit/orbit_taylor.hpp"
#include "newtop/phase/section_run.hpp"
#include "orbit_problems.hpp"

namespace newtop {
namespace test_orbit_taylor {
namespace {

using test::kOrbitEps;
using test::max_distance;

CircularOrbitModel circle() {
  return CircularOrbitModel(test::orbit_body(), CircularOrbit::from_rate(0.7));
}
EllipticOrbitModel ellipse(double e) {
  return EllipticOrbitModel(test::orbit_body(), EllipticOrbit::from_mean_motion(0.7, e, 0.4));
}

MethodSettings taylor(double tol) { return MethodSettings("taylor", 0.0, tol, tol); }

std::array<double, 9> numbers_of(const OrbitState& s) {
  return {s.m[0],     s.m[1],      s.m[2],      s.gamma[0], s.gamma[1],
          s.gamma[2], s.normal[0], s.normal[1], s.normal[2]};
}

OrbitState plus(const OrbitState& x, double a, const OrbitState& d) {
  return {x.m + a * d.m, x.gamma + a * d.gamma, x.normal + a * d.normal};
}

// x^[1] is the right-hand side to rounding (the same sums in another order: a few ε of the
// terms, O(1) here, so 16ε); x^[2] = ½ d/dt f(x(t)) against a central difference of f along f
// with ε = 1e-4: truncation ~ ε² |f'''| ~ 1e-8, rounding ~ ε_mach/ε ~ 1e-12, so 1e-7 (measured
// 7e-13 on the circle, 3.5e-9 on the ellipse; x^[1], 4.4e-16).
constexpr double kFirstCoefficient = 16 * kOrbitEps;
constexpr double kSecondCoefficient = 1e-7;

TEST(OrbitTaylor, FirstCoefficientsAreTheRightHandSideAndItsDerivative) {
  const CircularOrbitModel c = circle();
  const EllipticOrbitModel e = ellipse(0.3);
  const OrbitState x = test::tumbling_state(c.body());
  const double nu = 1.1, eps = 1e-4;
  detail::OrbitTaylorSeries sc, se;
  detail::orbit_taylor_expand(c, x, 12, sc);
  detail::orbit_taylor_expand(e, x, nu, 12, se);
  const OrbitState fc = rhs(c, x), fe = rhs(e, x, nu);
  const auto dc = numbers_of(plus(rhs(c, plus(x, eps, fc)), -1.0, rhs(c, plus(x, -eps, fc))));
  const auto de = numbers_of(
      plus(rhs(e, plus(x, eps, fe), nu + eps), -1.0, rhs(e, plus(x, -eps, fe), nu - eps)));
  const auto f1c = numbers_of(fc), f1e = numbers_of(fe);
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_NEAR(sc.x[1][i], f1c[i], kFirstCoefficient) << i;
    EXPECT_NEAR(se.x[1][i], f1e[i], kFirstCoefficient) << i;
    EXPECT_NEAR(sc.x[2][i], 0.25 * dc[i] / eps, kSecondCoefficient) << i;
    EXPECT_NEAR(se.x[2][i], 0.25 * de[i] / eps, kSecondCoefficient) << i;
  }
}

// At tol 1e-12 over 20 time units (~100 steps) against Fehlberg 7(8) at 1e-14: a global error of
// the steps' local errors of 1e-12 relative to O(1) numbers added up, so 1e-10 (measured 2e-12 to
// 4e-12); tol 1e-6 must be well off, or the comparison would not tell the tolerances apart.
constexpr double kGlobal12 = 1e-10;

TEST(OrbitTaylor, CircularRunAgreesWithFehlbergNearRoundOff) {
  const CircularOrbitModel c = circle();
  const OrbitState x0 = test::tumbling_state(c.body());
  const OrbitState ref = test::reference(c, x0, 0.0, 20.0);
  const OrbitOutcome fine = run_orbit_method(taylor(1e-12), c, x0, 0.0, 20.0, 1'000'000);
  const OrbitOutcome coarse = run_orbit_method(taylor(1e-6), c, x0, 0.0, 20.0, 1'000'000);
  ASSERT_EQ(fine.status, Status::finished);
  EXPECT_EQ(fine.t, 20.0);
  EXPECT_EQ(fine.rejected, 0);
  EXPECT_LT(max_distance(fine.state, ref), kGlobal12);
  EXPECT_GT(max_distance(coarse.state, ref), 100 * kGlobal12);
  // Order 21 against Fehlberg's 8: far fewer steps at the same tolerance.
  const OrbitOutcome rkf =
      run_orbit_method(MethodSettings("rkf78", 0.0, 1e-12, 1e-12), c, x0, 0.0, 20.0, 1'000'000);
  EXPECT_LT(2 * fine.steps, rkf.steps) << fine.steps << " " << rkf.steps;
  // Backwards from the end lands on the start.
  const OrbitOutcome back = run_orbit_method(taylor(1e-12), c, fine.state, 20.0, 0.0, 1'000'000);
  EXPECT_LT(max_distance(back.state, x0), 2 * kGlobal12);
}

TEST(OrbitTaylor, EllipticRunAgreesWithFehlbergNearRoundOff) {
  const EllipticOrbitModel e = ellipse(0.3);
  const OrbitState x0 = test::tumbling_state(e.body());
  const double nu1 = 0.4 + 4 * std::numbers::pi;
  const OrbitState ref = test::reference(e, x0, 0.4, nu1);
  const OrbitOutcome fine = run_orbit_method(taylor(1e-12), e, x0, 0.4, nu1, 1'000'000);
  ASSERT_EQ(fine.status, Status::finished);
  EXPECT_EQ(fine.t, nu1);
  EXPECT_LT(max_distance(fine.state, ref), kGlobal12);
  EXPECT_LT(casimir_error(fine.state), kGlobal12);
}

// The Jacobi integral of a circular orbit over 200 time units at tol 1e-13: each step's error is
// ~1e-13 relative and they add up over the ~1000 steps, as a random walk (√1000 ~ 30) or at worst
// linearly, so 1e-11 relative (measured 1.3e-13; a wrong recurrence drifts by O(1)).
TEST(OrbitTaylor, JacobiIntegralKeptToTheTolerance) {
  const CircularOrbitModel c = circle();
  const OrbitState x0 = test::tumbling_state(c.body());
  const double j0 = jacobi_integral(c, x0);
  double worst = 0.0;
  const OrbitObserver watch = [&](double, const OrbitState& x) {
    worst = std::max(worst, std::abs(jacobi_integral(c, x) - j0));
  };
  const OrbitOutcome o = run_orbit_method(taylor(1e-13), c, x0, 0.0, 200.0, 1'000'000, watch);
  ASSERT_EQ(o.status, Status::finished);
  EXPECT_LT(worst, 1e-11 * std::abs(j0));
  EXPECT_GT(worst, 0.0);  // the observer saw the steps
}

// On an ellipse of eccentricity 0, ν = ν0 + n t and the equations in ν are those in t on the
// circle of rate n: the same state at ν = ν0 + n t (both runs to 1e-13, each with a global error
// ~1e-13 of the O(1) numbers, so 1e-12; measured 1.7e-15: the two series differ only in σ = 1/n).
TEST(OrbitTaylor, EllipseOfEccentricityZeroIsTheCircle) {
  const double n = 0.7, t1 = 15.0;
  const CircularOrbitModel c(test::orbit_body(), CircularOrbit::from_rate(n));
  const EllipticOrbitModel e = ellipse(0.0);
  const OrbitState x0 = test::tumbling_state(c.body());
  const OrbitOutcome a = run_orbit_method(taylor(1e-13), c, x0, 0.0, t1, 1'000'000);
  const OrbitOutcome b = run_orbit_method(taylor(1e-13), e, x0, 0.4, 0.4 + n * t1, 1'000'000);
  EXPECT_LT(max_distance(a.state, b.state), 1e-12);
}

// The series is the continuous extension: output at every 0.37 time units (between the steps)
// against Fehlberg 7(8) at 1e-14 run to each time.
TEST(OrbitTaylor, SampledOutputIsTheSeriesBetweenSteps) {
  const CircularOrbitModel c = circle();
  const OrbitState x0 = test::tumbling_state(c.body());
  std::vector<std::pair<double, OrbitState>> got;
  const OrbitOutcome o = run_orbit_method_sampled(
      taylor(1e-12), c, x0, 0.0, 5.0, OutputTimes::every(0.37, 0.0, 5.0), 1'000'000,
      [&](std::int64_t, double t, const OrbitState& x) { got.emplace_back(t, x); });
  ASSERT_EQ(o.status, Status::finished);
  ASSERT_EQ(got.size(), 14u);
  for (const auto& [t, x] : got) {
    EXPECT_LT(max_distance(x, test::reference(c, x0, 0.0, t)), kGlobal12) << t;
  }
}

// A section with Taylor's series as the step map against dop853's: the same crossings to the
// two runs' errors (tol 1e-12 and 1e-13 over ~60 radians of ν: kGlobal12; measured 3e-12).
TEST(OrbitTaylor, SectionCrossingsAgreeWithDop853) {
  const EllipticOrbitModel e = ellipse(0.2);
  const OrbitState x0 = test::tumbling_state(e.body());
  const phase::SurfaceFunction g(phase::parse_surface("gamma3 = 0"), e.body(), true);
  auto crossings = [&](const MethodSettings& m) {
    std::vector<OrbitCrossing> out;
    OrbitSectionDrift drift;
    orbit_section(m, e, g, {phase::Direction::up, 6, false}, 0, x0, 0.4, 60.0, 100'000'000, out,
                  drift);
    return out;
  };
  const auto a = crossings(taylor(1e-12));
  const auto b = crossings(MethodSettings("dop853", 0.0, 1e-13, 1e-13));
  ASSERT_EQ(a.size(), 6u);
  ASSERT_EQ(b.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].t, b[i].t, kGlobal12) << i;
    EXPECT_LT(max_distance(a[i].x, b[i].x), kGlobal12) << i;
    EXPECT_LE(std::abs(g(a[i].x)), 8 * kOrbitEps * g.scale(a[i].x)) << i;
  }
}

TEST(OrbitTaylor, OrderFollowsTheTolerance) {
  EXPECT_EQ(OrbitTaylorStepper(1e-12, 1e-9).order(), detail::taylor_order(1e-12));
  EXPECT_EQ(OrbitTaylorStepper(1e-9, 1e-9, 12).order(), 12);
  EXPECT_THROW(OrbitTaylorStepper(1e-9, 1e-9, 31), InputError);
  EXPECT_THROW(OrbitTaylorStepper(0.0, 1e-9), InputError);
}

// The variational recurrences: δx^[1] is the Jacobian of orbit_stability.cpp (written apart from
// the recurrences) times δx, for each of nine independent directions, to rounding (the same
// products summed in another order, O(1) numbers: 16ε; measured 5.9ε); δx^[2] against the central
// difference of the state's x^[2] along δx (ε = 1e-6: truncation ~ ε² ~ 1e-12, rounding ~
// ε_mach/ε ~ 1e-10: 1e-8; measured 2.2e-10).
TEST(OrbitTaylor, TangentCoefficientsAreTheJacobianAndItsDerivative) {
  const CircularOrbitModel c = circle();
  const EllipticOrbitModel e = ellipse(0.3);
  const OrbitState x = test::tumbling_state(c.body());
  const double nu = 0.7, eps = 1e-6;
  for (int col = 0; col < 9; ++col) {
    std::array<double, 9> d{};
    for (int i = 0; i < 9; ++i) d[static_cast<std::size_t>(i)] = std::sin(1.0 + i + 3.0 * col);
    const OrbitState dx{Vec3(d[0], d[1], d[2]), Vec3(d[3], d[4], d[5]), Vec3(d[6], d[7], d[8])};
    for (int kind = 0; kind < 2; ++kind) {
      detail::OrbitTaylorSeries s, sp, sm;
      detail::OrbitTangentSeries ts;
      ts.columns = 1;
      ts.v[0][0] = d;
      Eigen::Matrix<double, 9, 9> J;
      if (kind == 0) {
        detail::orbit_taylor_expand(c, x, 8, s);
        detail::orbit_taylor_expand_tangent(c, s, ts);
        J = jacobian(c, x);
        detail::orbit_taylor_expand(c, plus(x, eps, dx), 8, sp);
        detail::orbit_taylor_expand(c, plus(x, -eps, dx), 8, sm);
      } else {
        detail::orbit_taylor_expand(e, x, nu, 8, s);
        detail::orbit_taylor_expand_tangent(e, s, nu, ts);
        J = jacobian(e, x, nu);
        detail::orbit_taylor_expand(e, plus(x, eps, dx), nu, 8, sp);
        detail::orbit_taylor_expand(e, plus(x, -eps, dx), nu, 8, sm);
      }
      const Eigen::Matrix<double, 9, 1> Jd =
          J * Eigen::Map<const Eigen::Matrix<double, 9, 1>>(d.data());
      for (std::size_t i = 0; i < 9; ++i) {
        EXPECT_NEAR(ts.v[0][1][i], Jd[static_cast<Eigen::Index>(i)],
                    kFirstCoefficient * (1 + std::abs(Jd[static_cast<Eigen::Index>(i)])))
            << "kind " << kind << ", direction " << col << ", component " << i;
        const double fd = (sp.x[2][i] - sm.x[2][i]) / (2 * eps);
        EXPECT_NEAR(ts.v[0][2][i], fd, 1e-8) << "kind " << kind << ", direction " << col;
      }
    }
  }
}

// Chaos on an orbit with Taylor's method against Fehlberg 7(8) on the same variational equations
// (both at 1e-12): the tangent map over a run (the flow's derivative, entries up to 4: each run's
// error ~1e-12 of them, so 1e-10; measured 1.2e-12 and 1.3e-12) and the indicators of a chaos run:
// λ_max (the sum of the logs of the renormalisations over t: 1e-9 relative; measured 1.4e-11) and
// MEGNO, whose time average is a sum over the accepted steps, so that methods with
// other steps differ by its quadrature (1 %, as docs/chaos.md holds the pairs to; measured 0.23 %).
TEST(OrbitTaylor, ChaosAgreesWithFehlbergsVariationalEquations) {
  const CircularOrbitModel c = circle();
  const EllipticOrbitModel e = ellipse(0.2);
  const OrbitState x = test::tumbling_state(c.body());
  const MethodSettings rkf78("rkf78", 0.0, 1e-12, 1e-12);
  const Eigen::Matrix<double, 9, 9> a = orbit_tangent_map(taylor(1e-12), c, x, 0.0, 5.0),
                                    b = orbit_tangent_map(rkf78, c, x, 0.0, 5.0);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-10 * (1 + b.cwiseAbs().maxCoeff()));
  const Eigen::Matrix<double, 9, 9> ae = orbit_tangent_map(taylor(1e-12), e, x, 0.4, 3.0),
                                    be = orbit_tangent_map(rkf78, e, x, 0.4, 3.0);
  EXPECT_LT((ae - be).cwiseAbs().maxCoeff(), 1e-10 * (1 + be.cwiseAbs().maxCoeff()));
  OrbitChaosSettings st;
  st.t1 = 40.0;
  st.method = taylor(1e-12);
  const OrbitChaosResult t = orbit_chaos(c, x, st);
  st.method = rkf78;
  const OrbitChaosResult r = orbit_chaos(c, x, st);
  ASSERT_EQ(t.outcome.status, Status::finished);
  EXPECT_EQ(t.t, 40.0);
  EXPECT_NEAR(t.indicators.megno, r.indicators.megno, 1e-2 * std::abs(r.indicators.megno));
  EXPECT_NEAR(t.indicators.lyapunov_max, r.indicators.lyapunov_max,
              1e-9 * std::abs(r.indicators.lyapunov_max));
  EXPECT_LT(t.outcome.steps, r.outcome.steps);  // a high order's longer steps
}

}  // namespace
}  // namespace test_orbit_taylor
}  // namespace newtop
