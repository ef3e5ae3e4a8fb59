// Taylor's method: its coefficients against the right-hand side and its derivative, the summed
// series against the closed-form free body and a reference near round-off, the order of a step,
// the error control, the attitude, a constant solution, the fields it refuses and the defaults.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "newtop/exact/mass_models.hpp"
#include "support/adaptive_checks.hpp"
#include "support/cli.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_taylor {
namespace {

using test::kEps;

Vec3 lanes3(const detail::TaylorSeries::Lanes& a) { return Vec3(a[0], a[1], a[2]); }

OrientedState generic_oriented(const QuadraticModel& m) {
  OrientedState x;
  static_cast<State&>(x) = test::generic_state(m);
  x.q = Quaternion(Eigen::AngleAxisd(0.7, Vec3(0.2, -0.4, 0.9).normalized()));
  return x;
}

Eigen::Vector4d wxyz(const Quaternion& q) { return Eigen::Vector4d(q.w(), q.x(), q.y(), q.z()); }

// x^[1] = f(x) to the rounding of f's terms (|m| |ω| + |γ| |∂V/∂γ| ≈ 10 here; 16 ε of that), and
// x^[2] = ½ (d/dt) f = ½ f'(x) f(x) against a central difference of f along f with δ = 1e-5: its
// truncation δ² |f'''|/6 ≲ 1e-9 and its rounding ε |f|/δ ≈ 1e-10 stay under kSecondOrder = 1e-8.
// The same for q̇ = ½ q ⊗ (0, ω).
constexpr double kSecondOrder = 1e-8;

TEST(TaylorSeries, FirstTwoCoefficientsAreTheRightHandSideAndItsDerivative) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const OrientedState x = generic_oriented(m);
  detail::TaylorSeries s;
  detail::taylor_expand(detail::TaylorModel(m), x, &x.q, 8, s);
  const State f = rhs(m, x);
  const double scale = 10.0;
  EXPECT_LT((lanes3(s.m[1]) - f.m).cwiseAbs().maxCoeff(), 16 * kEps * scale);
  EXPECT_LT((lanes3(s.gamma[1]) - f.gamma).cwiseAbs().maxCoeff(), 16 * kEps * scale);
  const Quaternion q1 = attitude_rate(x.q, omega(m.body, x));
  const Eigen::Vector4d series_q1(s.q[1][3], s.q[1][0], s.q[1][1], s.q[1][2]);
  EXPECT_LT((series_q1 - wxyz(q1)).cwiseAbs().maxCoeff(), 16 * kEps * scale);

  constexpr double d = 1e-5;
  const State up{x.m + d * f.m, x.gamma + d * f.gamma}, down{x.m - d * f.m, x.gamma - d * f.gamma};
  const State fu = rhs(m, up), fd = rhs(m, down);
  EXPECT_LT((lanes3(s.m[2]) - 0.25 * (fu.m - fd.m) / d).cwiseAbs().maxCoeff(), kSecondOrder);
  EXPECT_LT((lanes3(s.gamma[2]) - 0.25 * (fu.gamma - fd.gamma) / d).cwiseAbs().maxCoeff(),
            kSecondOrder);
  Quaternion qu = x.q, qd = x.q;
  qu.coeffs() += d * q1.coeffs();
  qd.coeffs() -= d * q1.coeffs();
  const Eigen::Vector4d q2 =
      0.25 *
      (wxyz(attitude_rate(qu, omega(m.body, up))) - wxyz(attitude_rate(qd, omega(m.body, down)))) /
      d;
  const Eigen::Vector4d series_q2(s.q[2][3], s.q[2][0], s.q[2][1], s.q[2][2]);
  EXPECT_LT((series_q2 - q2).cwiseAbs().maxCoeff(), kSecondOrder);
}

// The coefficients are the same bits with and without AVX2 (lane-wise operations in one order, no
// fused multiply-adds): a run's numbers do not depend on the processor it lands on.
TEST(TaylorSeries, SameBitsOnEveryInstructionSet) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const OrientedState x = generic_oriented(m);
  detail::TaylorSeries a, b;
  detail::taylor_expand(detail::TaylorModel(m), x, &x.q, 30, a);
  detail::taylor_expand(detail::TaylorModel(m), x, &x.q, 30, b, true);
  for (int n = 0; n <= 30; ++n) {
    const auto i = static_cast<std::size_t>(n);
    EXPECT_EQ(a.m[i], b.m[i]) << n;
    EXPECT_EQ(a.gamma[i], b.gamma[i]) << n;
    EXPECT_EQ(a.q[i], b.q[i]) << n;
  }
}

// The free body (g = λ = 0): the series of order 30 summed at h = 0.3 against the closed form of
// Euler–Poinsot (Jacobi functions and the precession angle). The terms fall like (h/ρ)^n with ρ,
// the distance to the nearest complex singularity, above 1 here: the truncation is below 1e-20,
// and the sum's rounding is a few ε of |x| ≈ 2 (kSummed = 1e-14).
constexpr double kSummed = 1e-14;

TEST(TaylorSeries, SummedSeriesIsTheClosedFormOfTheFreeBody) {
  const Body body = Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero());
  const QuadraticModel m{body, QuadraticField::coulomb(0.0, 0.0)};
  const State x0 = state_from_omega(body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
  detail::TaylorSeries s;
  detail::taylor_expand(detail::TaylorModel(m), x0, nullptr, 30, s);
  for (double h : {0.1, -0.2, 0.3}) {
    const State exact = free_body_state(euler_poinsot(body, x0), h);
    EXPECT_LT(test::distance(detail::taylor_state(s, h), exact), kSummed) << "h = " << h;
  }
}

// With the whole field (gyrostat, centre of mass off the axes, λ) against Fehlberg 7(8) at 1e-15
// over the same short spans (its error there ≲ 1e-15 per unit time; bound 10 kSummed).
TEST(TaylorSeries, SummedSeriesAgreesWithAReferenceNearRoundOff) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const State x0 = test::generic_state(m);
  detail::TaylorSeries s;
  detail::taylor_expand(detail::TaylorModel(m), x0, nullptr, 30, s);
  for (double h : {0.1, 0.3}) {
    const State ref = test::reference_solution(m, x0, h, 1e-15);
    EXPECT_LT(test::distance(detail::taylor_state(s, h), ref), 10 * kSummed) << "h = " << h;
  }
}

// One step of the series truncated at order p from the generic state: the error of a step of h
// against the reference falls as h^(p+1); for p = 6 and 9, the observed exponent from h = 0.4
// and 0.2 within 0.5 of p + 1 (errors far above the reference's ~1e-15, checked).
TEST(Taylor, ObservedOrderOfAStep) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const State x0 = test::generic_state(m);
  for (int p : {6, 9}) {
    detail::TaylorSeries s;
    detail::taylor_expand(detail::TaylorModel(m), x0, nullptr, p, s);
    const double e1 =
        test::distance(detail::taylor_state(s, 0.4), test::reference_solution(m, x0, 0.4, 1e-15));
    const double e2 =
        test::distance(detail::taylor_state(s, 0.2), test::reference_solution(m, x0, 0.2, 1e-15));
    ASSERT_GT(e2, 1e-12) << "p = " << p << ": error at round-off, the order is not observable";
    EXPECT_NEAR(std::log2(e1 / e2), p + 1.0, 0.5) << "p = " << p << ": " << e1 << ", " << e2;
  }
}

// The error control: over T = 10 of the generic model the error at T falls with the tolerance,
// by at least 10× for each 100×, and stays within kTolFactor tol. Each step's truncation is about
// ε (h/ρ) e^(−0.7/(p−1)) < tol (the last two coefficients set h), local errors grow along this
// orbit by e^(λT) ≈ 2.3, and ~100..1000 steps add up with signs that do not all agree: 10 as for
// the Runge–Kutta pairs (measured 0.24, 0.15 and 0.26 tol, in 21, 22 and 25 steps).
constexpr double kTolFactor = 10.0;

TEST(Taylor, ErrorFollowsTheTolerance) {
  test::expect_error_follows_the_tolerance([](double tol) { return TaylorStepper(tol, tol); },
                                           kTolFactor);
}

// Every step is accepted: the step comes from the coefficients, it is never tried.
TEST(Taylor, StepsAreNeverRejected) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  TaylorStepper s(1e-10, 1e-10);
  const Outcome o = integrate(s, m, test::generic_state(m), 0.0, 10.0, IntegrateOptions{});
  ASSERT_EQ(o.status, Status::finished);
  EXPECT_EQ(o.rejected, 0);
  EXPECT_GT(o.steps, 10);
}

// With an attitude: the state and q against Fehlberg 7(8) with an attitude at 1e-13 over T = 20
// (bound 1e-9, as for Dormand–Prince 8(5,3)), the renormalisation of q within the tolerance's
// size, and the series of a first step at mid-step against the same reference.
TEST(Taylor, CarriesTheAttitude) {
  test::expect_carries_the_attitude([] { return TaylorStepper(1e-12, 1e-12); });
}

// An equilibrium (at rest, γ along the axis of least moment of a gravity gradient, r0 = 0): every
// coefficient past the first vanishes, the step is unbounded, and one step lands on t1 with the
// state unchanged.
TEST(Taylor, ConstantSolutionIsOneStep) {
  const QuadraticModel m{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                         QuadraticField::coulomb(0.0, 1.0)};
  const State x0{Vec3::Zero(), Vec3::UnitX()};
  TaylorStepper s(1e-12, 1e-12);
  EXPECT_TRUE(std::isinf(s.initial_step(m, x0, 0.0, 100.0)));
  const Outcome o = integrate(s, m, x0, 0.0, 100.0, IntegrateOptions{});
  ASSERT_EQ(o.status, Status::finished);
  EXPECT_EQ(o.steps, 1);
  EXPECT_EQ(o.state, x0);
}

// One stepper, two models at the same point: a step of the second is of the second model (the
// series at hand is kept only for the same point of the same model).
TEST(Taylor, AStepperReusedOnAnotherModelExpandsAgain) {
  const QuadraticModel a = test::generic_model();
  QuadraticModel b = a;
  b.field.lambda_ = 2.0;
  const State x0 = test::generic_state(a);
  TaylorStepper s(1e-12, 1e-12), fresh(1e-12, 1e-12);
  s.initial_step(a, x0, 0.0, 1.0);  // the series of a through x0 is at hand
  State xb = x0, xf = x0;
  double tb = 0.0, tf = 0.0, db = 0.1, df = 0.1;
  ASSERT_TRUE(s.try_step(b, xb, tb, db));
  ASSERT_TRUE(fresh.try_step(b, xf, tf, df));
  EXPECT_EQ(xb, xf);
}

// The order follows the tolerance (docs/methods.md): ⌈0.6 |ln tol|⌉ + 4 within [8, 30].
TEST(Taylor, OrderFollowsTheTolerance) {
  EXPECT_EQ(TaylorStepper(1e-6, 1e-6).order(), 13);
  EXPECT_EQ(TaylorStepper(1e-12, 1e-12).order(), 21);
  EXPECT_EQ(TaylorStepper(1e-16, 1e-10).order(), 27);
  EXPECT_EQ(TaylorStepper(1e-2, 1e-2).order(), 8);
  EXPECT_EQ(TaylorStepper(1e-12, 1e-12, 5).order(), 5);
  EXPECT_THROW(TaylorStepper(1e-12, 1e-12, 41), InputError);
  EXPECT_THROW(TaylorStepper(0.0, 1e-12), InputError);
}

TEST(Taylor, OtherFieldsAreRefused) {
  const auto points = std::make_shared<const MassModel>(
      PointMasses({1.0, 2.0}, {Vec3(1.0, 0.2, 0.0), Vec3(-0.5, -0.1, 0.0)}));
  const Model exact = Model::exact(points, 1.0, 3.0);
  const State x0{Vec3(0.1, 0.2, 0.3), Vec3::UnitZ()};
  const MethodSettings taylor{"taylor", 0.0, 1e-10, 1e-10, std::nullopt};
  EXPECT_THROW(run_method(taylor, exact, x0, 0.0, 1.0), InputError);

  const test::CliResult r = test::run_newtop(
      "simulate " + test::example_path("exact_box_multipole.toml") + " --method taylor --tol 1e-10",
      test::Stderr::separate);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("method: taylor expands the quadratic field only"), std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// With a tolerance and no method: taylor on the quadratic field (with and without the chaos
// indicators' tangent map), dop853 on an exact or multipole field (docs/performance.md, "The
// default method").
TEST(Taylor, DefaultWithAToleranceFollowsTheFieldAndTheCommand) {
  auto method_of = [](const std::string& args) {
    const test::CliResult r = test::run_newtop(args + " --json", test::Stderr::separate);
    EXPECT_EQ(r.code, 0) << args << ": " << r.err;
    return r.code == 0 ? nlohmann::json::parse(r.out)["method"].get<std::string>() : "";
  };
  EXPECT_EQ(method_of("simulate " + test::example_path("brun.toml") + " --t-end 1 --tol 1e-10"),
            "taylor");
  EXPECT_EQ(method_of("simulate " + test::example_path("exact_box_multipole.toml") +
                      " --t-end 0.5 --tol 1e-10"),
            "dop853");
  EXPECT_EQ(method_of("chaos " + test::example_path("brun.toml") + " --t-end 2 --tol 1e-10"),
            "taylor");
  EXPECT_EQ(method_of("chaos " + test::example_path("exact_box_multipole.toml") +
                      " --t-end 0.5 --tol 1e-10"),
            "dop853");
}

TEST(Taylor, CommandLineNamesIt) {
  const nlohmann::json j = test::expect_command_line_runs("taylor");
  EXPECT_EQ(j["order"], 20);  // ⌈0.6 |ln 1e-11|⌉ + 4
  EXPECT_EQ(j["rejected_steps"], 0);
}

}  // namespace
}  // namespace test_taylor
}  // namespace newtop
