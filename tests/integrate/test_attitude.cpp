// The attitude R (body → inertial, a unit quaternion) carried beside (m, γ). The fixed inertial
// direction e = R(0) γ(0) must satisfy γ = Rᵀ e all along a run: the splitting turns R's rows with
// the very rotations that turn γ, so there the two agree to round-off; the Runge–Kutta methods
// integrate q̇ = ½ q ⊗ (0, ω) beside γ̇ = γ × ω, so there they agree to the tolerance. The free
// body's closed form (Euler angles about the angular momentum) is the independent reference for
// the attitude itself.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>

#include "support/problems.hpp"

namespace newtop {
namespace test_attitude {
namespace {

using test::kEps;

OrientedState oriented(const State& x) {
  return with_attitude(x, from_euler_321(Vec3(0.7, -0.4, 2.1)));
}

/// |γ − Rᵀe|.
double vertical_defect(const OrientedState& x, const Vec3& e) {
  return (x.gamma - x.q.conjugate() * e).norm();
}

SplittingStepper splitting(const char* name, FreeBodySplit split) {
  const CompositionTable& t = composition_table(name);
  SplitOrdering o = default_ordering(t);
  o.free_body = split;
  return SplittingStepper(t, o);
}

// --- Splitting: γ = Rᵀe to round-off. Each sub-flow rounds γ and the rows of R once (about ε
// each, unbiased), and the end of a step rounds the quaternion of R once more: after N steps of S
// sub-flows the difference is a random walk of about ε √(N (S + 1)). The bound allows 4 standard
// deviations (kWalkSigmas) of a walk whose steps are up to 2 ε (a rounding of γ and one of R).
constexpr double kWalkSigmas = 4.0;
constexpr double kRoundingPerSubFlow = 2.0 * kEps;

double walk_bound(std::int64_t steps, std::size_t stages) {
  return kWalkSigmas * kRoundingPerSubFlow *
         std::sqrt(static_cast<double>(steps) * static_cast<double>(stages + 1));
}

struct SplitCase {
  const char* name;
  FreeBodySplit split;
  bool gyrostat;
};

std::ostream& operator<<(std::ostream& os, const SplitCase& c) {
  return os << c.name << " split " << static_cast<int>(c.split) << (c.gyrostat ? " gyrostat" : "");
}

class SplittingAttitude : public ::testing::TestWithParam<SplitCase> {};

TEST_P(SplittingAttitude, GammaIsRTransposeEToRoundOff) {
  const SplitCase c = GetParam();
  const QuadraticModel m = test::generic_model(c.gyrostat ? Vec3(0.1, -0.2, 0.3) : Vec3::Zero());
  SplittingStepper s = splitting(c.name, c.split);
  OrientedState x = oriented(test::generic_state(m));
  const Vec3 e = inertial_direction(x);
  constexpr std::int64_t kSteps = 20000;
  double worst_ratio = 0.0;
  for (std::int64_t i = 1; i <= kSteps; ++i) {
    s.step(m, x, 0.01);
    if (i % 100 == 0) {
      worst_ratio = std::max(worst_ratio, vertical_defect(x, e) / walk_bound(i, s.stages()));
    }
  }
  EXPECT_LE(worst_ratio, 1.0) << c.name;
  // R stays a rotation: q is unit, and the renormalisation at the end of a step removes only the
  // round-off of that step's S sub-flows.
  EXPECT_LE(orthonormality_defect(x.q.toRotationMatrix()), 4 * kEps);
  EXPECT_LE(s.attitude_projection(), kRoundingPerSubFlow * static_cast<double>(s.stages() + 1));
  EXPECT_GT(s.attitude_projection(), 0.0);  // the projection is measured, not assumed
}

INSTANTIATE_TEST_SUITE_P(Methods, SplittingAttitude,
                         ::testing::Values(SplitCase{"splitting2", FreeBodySplit::axes, true},
                                           SplitCase{"splitting6", FreeBodySplit::axes, false},
                                           SplitCase{"splitting4", FreeBodySplit::spin, false},
                                           SplitCase{"splitting6", FreeBodySplit::spin, true},
                                           SplitCase{"splitting4", FreeBodySplit::exact, false}));

// The state (m, γ) of a run is the same with or without the attitude: the attitude is a passenger.
TEST(SplittingAttitude, AttitudeDoesNotChangeThePhasePoint) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  for (const FreeBodySplit split : {FreeBodySplit::axes, FreeBodySplit::spin}) {
    SplittingStepper a = splitting("splitting6", split), b = a;
    State x = test::generic_state(m);
    OrientedState y = oriented(x);
    for (int i = 0; i < 1000; ++i) {
      a.step(m, x, 0.01);
      b.step(m, y, 0.01);
    }
    EXPECT_EQ(x, static_cast<const State&>(y));
  }
}

// --- Runge–Kutta: γ = Rᵀe to the tolerance. δ = γ − Rᵀe obeys δ̇ = δ × ω between steps (both
// terms move as body-frame images of fixed vectors), which keeps |δ|: δ only collects the local
// errors. Each accepted step's local error is below tol (abs_tol + rel_tol (|y_i| + h |y'_i|)) ≤
// 3 tol per component for |y_i|, h|y'_i| ≤ 1, so |δ| ≤ 2 · √3 · 3 tol per step (γ and q each).
constexpr double kLocalErrorPerStep = 2.0 * std::numbers::sqrt3 * 3.0;

template <class S>
void expect_vertical_to_tolerance(S stepper, double tol) {
  const QuadraticModel m = test::generic_model();
  const OrientedState x0 = oriented(test::generic_state(m));
  const Vec3 e = inertial_direction(x0);
  double worst = 0.0;
  auto obs = [&](double, const OrientedState& x) {
    worst = std::max(worst, vertical_defect(x, e));
  };
  const Outcome out = integrate(stepper, m, x0, 0.0, 20.0, IntegrateOptions{}, obs);
  ASSERT_EQ(out.status, Status::finished);
  ASSERT_TRUE(out.attitude.has_value());
  EXPECT_LE(worst, kLocalErrorPerStep * tol * static_cast<double>(out.steps));
  // The renormalisation is the drift of ‖q‖ in one step: within the error control.
  EXPECT_LE(out.attitude_projection, kLocalErrorPerStep * tol);
  EXPECT_LE(orthonormality_defect(out.attitude->toRotationMatrix()), 4 * kEps);
}

TEST(RungeKuttaAttitude, GammaIsRTransposeEToTheTolerance) {
  expect_vertical_to_tolerance(Fehlberg78Stepper(1e-11, 1e-11), 1e-11);
  expect_vertical_to_tolerance(Dopri5Stepper(1e-9, 1e-9), 1e-9);
}

// --- The attitude itself against the free body's closed form. Free body: λ = 0, g = 0, k = 0.
QuadraticModel free_body() {
  return QuadraticModel{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                        QuadraticField::coulomb(0.0, 0.0)};
}

/// The attitude of the closed form in the frame N of the angular momentum (free_body_euler_angles).
Quaternion closed_form_in_n(const EulerPoinsot& s, double t) {
  return from_euler_313(free_body_euler_angles(s, t)) * free_body_pole_frame(s);
}

/// The rotation R_z(φ) R_x(θ) R_z(ψ) of an integrated attitude: R_N(t) Q⁻¹, with R_N(t) = R_N(0)
/// R(0)ᵀ R(t) its attitude in N.
Quaternion integrated_euler_rotation(const EulerPoinsot& s, const Quaternion& q0,
                                     const Quaternion& q) {
  return closed_form_in_n(s, 0.0) * q0.conjugate() * q * free_body_pole_frame(s).conjugate();
}

double angle_difference(double a, double b) {
  return std::abs(std::remainder(a - b, 2 * std::numbers::pi));
}

// Euler angles: the integrated attitude's precession, nutation and spin about the angular
// momentum against the closed form's, over three periods of m(t), integrated by rkf78 at tol 1e-12:
// the attitude collects at most kLocalErrorPerStep · tol per step (as δ above), and the angles are
// within a factor 1/sin θ of it (sin θ > 0.3 here).
TEST(FreeBodyAttitude, EulerAnglesMatchTheClosedForm) {
  const QuadraticModel m = free_body();
  ASSERT_TRUE(euler_poinsot_holds(m));
  const OrientedState x0 = oriented(state_from_omega(m.body, Vec3(0.4, 1.0, 0.6), Vec3::UnitZ()));
  const EulerPoinsot s = euler_poinsot(m.body, x0);
  ASSERT_FALSE(s.permanent);
  Fehlberg78Stepper rk(1e-12, 1e-12);
  double worst = 0.0, worst_rotation = 0.0, min_sin = 1.0;
  auto obs = [&](double t, const OrientedState& x) {
    const Vec3 closed = free_body_euler_angles(s, t);
    const Vec3 integrated = euler_313(integrated_euler_rotation(s, x0.q, x.q));
    min_sin = std::min(min_sin, std::sin(closed[1]));
    for (int i = 0; i < 3; ++i) worst = std::max(worst, angle_difference(closed[i], integrated[i]));
    worst_rotation =
        std::max(worst_rotation, rotation_distance(x.q, free_body_attitude(s, x0.q, t)));
  };
  const Outcome out = integrate(rk, m, x0, 0.0, 3 * s.period, IntegrateOptions{}, obs);
  ASSERT_EQ(out.status, Status::finished);
  ASSERT_GT(min_sin, 0.3);
  const double bound = kLocalErrorPerStep * 1e-12 * static_cast<double>(out.steps);
  EXPECT_LE(worst, bound / min_sin);
  EXPECT_LE(worst_rotation, bound);
}

// Convergence of a splitting's attitude to the closed form: splitting4 (axes split, order 4) at
// steps h and h/2 over one period of m(t); the error must fall by 2⁴ within ±30%.
TEST(FreeBodyAttitude, SplittingAttitudeConvergesAtItsOrder) {
  const QuadraticModel m = free_body();
  const OrientedState x0 = oriented(state_from_omega(m.body, Vec3(0.4, 1.0, 0.6), Vec3::UnitZ()));
  const EulerPoinsot s = euler_poinsot(m.body, x0);
  auto error = [&](std::int64_t n) {
    SplittingStepper st = splitting("splitting4", FreeBodySplit::axes);
    IntegrateOptions opt;
    opt.step = s.period / static_cast<double>(n);
    const Outcome out = integrate(st, m, x0, 0.0, s.period, opt);
    return rotation_distance(*out.attitude, free_body_attitude(s, x0.q, s.period));
  };
  const double e1 = error(200), e2 = error(400);
  EXPECT_LE(e1, 1e-4);
  EXPECT_NEAR(e1 / e2, 16.0, 0.3 * 16.0);
}

// rk4 carries q̇ = ½ q ⊗ (0, ω) at its order: the attitude's error against the closed form falls by
// 2⁴ = 16 (±30%) when the step is halved, and γ = Rᵀe holds to the errors of γ and R.
TEST(FreeBodyAttitude, Rk4AttitudeConvergesAtItsOrder) {
  const QuadraticModel m = free_body();
  const OrientedState x0 = oriented(state_from_omega(m.body, Vec3(0.4, 1.0, 0.6), Vec3::UnitZ()));
  const EulerPoinsot s = euler_poinsot(m.body, x0);
  const Vec3 e = inertial_direction(x0);
  auto error = [&](std::int64_t n) {
    Rk4Stepper st;
    IntegrateOptions opt;
    opt.step = s.period / static_cast<double>(n);
    const Outcome out = integrate(st, m, x0, 0.0, s.period, opt);
    const double err = rotation_distance(*out.attitude, free_body_attitude(s, x0.q, s.period));
    // Triangle inequality: |γ − Rᵀe| ≤ |γ − γ_exact| + |(R_exact − R)ᵀ e|, the last at most the
    // angle between R and R_exact.
    const double gamma_err = (out.state.gamma - free_body_state(s, s.period).gamma).norm();
    EXPECT_LE(vertical_defect(with_attitude(out.state, *out.attitude), e),
              gamma_err + err + 8 * kEps);
    return err;
  };
  const double e1 = error(400), e2 = error(800);
  EXPECT_LE(e1, 1e-5);
  EXPECT_NEAR(e1 / e2, 16.0, 0.3 * 16.0);
}

// The splitting with the exact free-body flow carries the attitude through that flow's own
// rotation: on the free body it is exact, to round-off, at any step.
TEST(FreeBodyAttitude, ExactSplitIsExactOnTheFreeBody) {
  const QuadraticModel m = free_body();
  const OrientedState x0 = oriented(state_from_omega(m.body, Vec3(0.4, 1.0, 0.6), Vec3::UnitZ()));
  const EulerPoinsot s = euler_poinsot(m.body, x0);
  SplittingStepper st = splitting("splitting2", FreeBodySplit::exact);
  IntegrateOptions opt;
  opt.step = s.period / 7.0;
  const Outcome out = integrate(st, m, x0, 0.0, 2 * s.period, opt);
  // Against the rkf78 run at 1e-13 (an independent integration): agreement to its tolerance.
  Fehlberg78Stepper rk(1e-13, 1e-13);
  const Outcome ref = integrate(rk, m, x0, 0.0, 2 * s.period, IntegrateOptions{});
  EXPECT_LE(rotation_distance(*out.attitude, *ref.attitude), 1e-10);
}

// Output at requested times carries the attitude: the continuous extensions of rkf78 (Hermite, on
// q's four numbers as well) and dopri5 (its own), and a splitting that lands on every output time,
// against the closed form. The interpolant's error is of the order of one step's local error, so
// the bound is that of the run plus one step.
TEST(FreeBodyAttitude, OutputTimesCarryTheAttitude) {
  const QuadraticModel m = free_body();
  const OrientedState x0 = oriented(state_from_omega(m.body, Vec3(0.4, 1.0, 0.6), Vec3::UnitZ()));
  const EulerPoinsot s = euler_poinsot(m.body, x0);
  const OutputTimes times = OutputTimes::every(0.37, 0.0, 10.0);
  auto worst_error = [&](auto stepper, double step) {
    double worst = 0.0;
    std::int64_t samples = 0;
    auto sample = [&](std::int64_t, double t, const OrientedState& x) {
      worst = std::max(worst, rotation_distance(x.q, free_body_attitude(s, x0.q, t)));
      ++samples;
    };
    IntegrateOptions opt;
    opt.step = step;
    const Outcome out = integrate_sampled(stepper, m, x0, 0.0, 10.0, times, opt, sample);
    EXPECT_EQ(samples, times.size());
    return std::pair{worst, out.steps};
  };
  for (const double tol : {1e-12, 1e-9}) {
    const auto [rkf, rkf_steps] = worst_error(Fehlberg78Stepper(tol, tol), 0.0);
    EXPECT_LE(rkf, kLocalErrorPerStep * tol * static_cast<double>(rkf_steps + 1)) << tol;
    const auto [dp, dp_steps] = worst_error(Dopri5Stepper(tol, tol), 0.0);
    EXPECT_LE(dp, kLocalErrorPerStep * tol * static_cast<double>(dp_steps + 1)) << tol;
  }
  // splitting2 (order 2) at h = 0.01 and 0.02: the attitude at the output times converges at its
  // order, the error falling by 2² = 4 within ±30%.
  const double fine = worst_error(splitting("splitting2", FreeBodySplit::axes), 0.01).first;
  const double coarse = worst_error(splitting("splitting2", FreeBodySplit::axes), 0.02).first;
  EXPECT_NEAR(coarse / fine, 4.0, 0.3 * 4.0);
  EXPECT_LE(fine, 1e-3);
}

// Conventions of the Euler angles: round trips, and the stated rotations.
TEST(EulerAngles, ConventionsAndRoundTrips) {
  const double a = 0.3;
  // 3-2-1 yaw ψ alone is R_z(ψ): the body x axis goes to (cos ψ, sin ψ, 0).
  EXPECT_LE(
      (from_euler_321(Vec3(a, 0, 0)) * Vec3::UnitX() - Vec3(std::cos(a), std::sin(a), 0)).norm(),
      4 * kEps);
  // 3-2-1 pitch θ alone is R_y(θ): the body x axis goes to (cos θ, 0, −sin θ).
  EXPECT_LE(
      (from_euler_321(Vec3(0, a, 0)) * Vec3::UnitX() - Vec3(std::cos(a), 0, -std::sin(a))).norm(),
      4 * kEps);
  // 3-1-3 nutation θ alone is R_x(θ): the body z axis goes to (0, −sin θ, cos θ).
  EXPECT_LE(
      (from_euler_313(Vec3(0, a, 0)) * Vec3::UnitZ() - Vec3(0, -std::sin(a), std::cos(a))).norm(),
      4 * kEps);
  for (const Vec3& v : {Vec3(0.7, -0.4, 2.1), Vec3(-3.0, 1.2, -0.1), Vec3(2.5, -1.5, 3.1)}) {
    EXPECT_LE((euler_321(from_euler_321(v)) - v).norm(), 16 * kEps) << v.transpose();
  }
  for (const Vec3& v : {Vec3(0.7, 0.4, 2.1), Vec3(-3.0, 2.9, -0.1), Vec3(2.5, 1.5, 3.1)}) {
    EXPECT_LE((euler_313(from_euler_313(v)) - v).norm(), 16 * kEps) << v.transpose();
  }
  // Singular angles: the rotation is still reproduced.
  for (const Vec3& v :
       {Vec3(0.4, std::numbers::pi / 2, 0.0), Vec3(0.4, -std::numbers::pi / 2, 0.0)}) {
    EXPECT_LE(rotation_distance(from_euler_321(euler_321(from_euler_321(v))), from_euler_321(v)),
              1e-7);
  }
  for (const Vec3& v : {Vec3(0.4, 0.0, 0.0), Vec3(0.4, std::numbers::pi, 0.0)}) {
    EXPECT_LE(rotation_distance(from_euler_313(euler_313(from_euler_313(v))), from_euler_313(v)),
              1e-7);
  }
}

TEST(AttitudeInput, NonUnitQuaternionIsBadInput) {
  const QuadraticModel m = test::generic_model();
  OrientedState x = oriented(test::generic_state(m));
  x.q.coeffs() *= 1.01;
  SplittingStepper s = splitting("splitting2", FreeBodySplit::axes);
  IntegrateOptions opt;
  opt.step = 0.1;
  EXPECT_THROW(integrate(s, m, x, 0.0, 1.0, opt), InputError);
}

}  // namespace
}  // namespace test_attitude
}  // namespace newtop
