// The orbit model's equations against independent derivations: the Lie–Poisson form of the
// Jacobi integral (finite-difference gradients), the conservation laws, a direct simulation of the
// satellite in inertial space, and Kepler's time against a quadrature.

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "inertial_reference.hpp"
#include "orbit_problems.hpp"

namespace newtop {
namespace test_orbit_model {
namespace {

using test::kOrbitEps;

/// The Lie–Poisson bracket of so(3) ⋉ (ℝ³ ⊕ ℝ³) applied to a generator with gradient
/// (Hm, Hg, Hn): ṁ = m × Hm + γ × Hg + n × Hn, γ̇ = γ × Hm, ṅ = n × Hm.
OrbitState bracket(const OrbitState& s, const Vec3& Hm, const Vec3& Hg, const Vec3& Hn) {
  return {s.m.cross(Hm) + s.gamma.cross(Hg) + s.normal.cross(Hn), s.gamma.cross(Hm),
          s.normal.cross(Hm)};
}

/// Central-difference gradient of a function of the 9 components.
template <class F>
void fd_gradient(const F& H, const OrbitState& s, double d, Vec3& Hm, Vec3& Hg, Vec3& Hn) {
  for (int i = 0; i < 3; ++i) {
    for (auto [field, out] : {std::pair{&OrbitState::m, &Hm}, std::pair{&OrbitState::gamma, &Hg},
                              std::pair{&OrbitState::normal, &Hn}}) {
      OrbitState p = s, q = s;
      (p.*field)[i] += d;
      (q.*field)[i] -= d;
      (*out)[i] = (H(p) - H(q)) / (2 * d);
    }
  }
}

// H is a polynomial of degree 2 in (m, γ, n): central differences have no truncation error, only
// round-off eps·|H|/δ ≈ 1e-12 with δ = 1e-4 and |H| = O(10); 1e-10 leaves a factor 100.
constexpr double kGradientTolerance = 1e-10;

TEST(OrbitModel, CircularEquationsAreTheLiePoissonFlowOfTheJacobiIntegral) {
  const CircularOrbitModel model(test::orbit_body(), CircularOrbit::from_rate(0.7));
  const OrbitState s = test::tumbling_state(model.body());
  Vec3 Hm, Hg, Hn;
  fd_gradient([&](const OrbitState& x) { return jacobi_integral(model, x); }, s, 1e-4, Hm, Hg, Hn);
  EXPECT_LT(test::max_distance(bracket(s, Hm, Hg, Hn), rhs(model, s)), kGradientTolerance);
}

TEST(OrbitModel, EllipticEquationsAreTheLiePoissonFlowOfTheAnomalyHamiltonian) {
  const EllipticOrbitModel model(test::orbit_body(),
                                 EllipticOrbit::from_mean_motion(0.7, 0.4, 0.0));
  const OrbitState s = test::tumbling_state(model.body());
  for (double nu : {0.0, 1.3, 2.9}) {
    Vec3 Hm, Hg, Hn;
    fd_gradient([&](const OrbitState& x) { return hamiltonian(model, x, nu); }, s, 1e-4, Hm, Hg,
                Hn);
    EXPECT_LT(test::max_distance(bracket(s, Hm, Hg, Hn), rhs(model, s, nu)), kGradientTolerance);
  }
}

// The rates of the Casimirs and of the Jacobi integral along the vector field vanish identically;
// evaluated in floating point they are sums of O(10) terms: 64 eps.
constexpr double kIdentity = 64 * kOrbitEps;

TEST(OrbitModel, VectorFieldIsTangentToCasimirsAndKeepsJacobiIntegral) {
  const CircularOrbitModel model(test::orbit_body(), CircularOrbit::from_rate(0.7));
  const OrbitState s = test::tumbling_state(model.body());
  const OrbitState f = rhs(model, s);
  EXPECT_LT(std::abs(s.gamma.dot(f.gamma)), kIdentity);
  EXPECT_LT(std::abs(s.normal.dot(f.normal)), kIdentity);
  EXPECT_LT(std::abs(f.gamma.dot(s.normal) + s.gamma.dot(f.normal)), kIdentity);
  // dH/dt = ∇H·f with the exact gradient (ω − ω0 n, λIγ, −ω0 m).
  const Body& b = model.body();
  const double w0 = model.orbit().rate;
  const double dH = (omega(b, s) - w0 * s.normal).dot(f.m) +
                    model.orbit().lambda_ * b.inertia().cwiseProduct(s.gamma).dot(f.gamma) -
                    w0 * s.m.dot(f.normal);
  EXPECT_LT(std::abs(dH), kIdentity);
}

// Both simulations run Fehlberg 7(8) at 1e-14 over about two orbits (~1e3 steps): their global
// errors are ~1e-12; the bound is the 1e-10.
constexpr double kInertialAgreement = 1e-10;

struct InertialSetup {
  test::InertialProblem problem;
  test::InertialSatellite x0;
  Vec3 N;  // inertial orbit normal
};

OrbitState body_view(const test::InertialSatellite& x, const Vec3& N, const Body& body) {
  (void)body;
  return {x.R.transpose() * x.L, x.R.transpose() * x.r.normalized(), x.R.transpose() * N};
}

/// A satellite on a Kepler orbit of (μ, a, e) at true anomaly ν0, in an orbit plane and with an
/// attitude that share no axis with the inertial frame.
InertialSetup setup(const Body& body, double mu, double a, double e, double nu0, const Vec3& w) {
  const Mat3 Q = test::rotation(0.3, 0.7, -0.2, 0.5);  // perifocal → inertial
  const double p = a * (1 - e * e);
  const Vec3 r = p / (1 + e * std::cos(nu0)) * Vec3(std::cos(nu0), std::sin(nu0), 0);
  const Vec3 v = std::sqrt(mu / p) * Vec3(-std::sin(nu0), e + std::cos(nu0), 0);
  const Mat3 R = test::rotation(0.9, 0.1, -0.4, 0.3);
  return {{mu, body.inertia(), body.gyrostat()},
          {Q * r, Q * v, R, R * (body.inertia().cwiseProduct(w) + body.gyrostat())},
          Q.col(2)};
}

TEST(OrbitModel, CircularOrbitAgreesWithInertialSimulation) {
  const Body body = test::orbit_body();
  const double mu = 1.0, radius = 1.3;
  const CircularOrbitModel model(body, CircularOrbit::from_mu_radius(mu, radius));
  const InertialSetup is = setup(body, mu, radius, 0.0, 0.4, Vec3(0.3, -0.5, 0.9));
  const double T = 2 * (2 * std::numbers::pi / model.orbit().rate);
  const OrbitState x0 = body_view(is.x0, is.N, body);
  const OrbitState inertial = body_view(test::inertial_flow(is.problem, is.x0, T), is.N, body);
  EXPECT_LT(test::max_distance(test::reference(model, x0, 0.0, T), inertial), kInertialAgreement);
  // The order-8 splitting at h = 0.01 (error ~1e-14, see the order test) agrees as well.
  const OrbitSplittingStepper s8(composition_table("splitting8"));
  EXPECT_LT(test::max_distance(integrate(s8, model, x0, 0.0, T, 0.01).state, inertial),
            kInertialAgreement);
}

TEST(OrbitModel, EllipticOrbitAgreesWithInertialSimulation) {
  const Body body = test::orbit_body();
  const double mu = 1.0, a = 1.3, e = 0.3, nu0 = 0.7, T = 20.0;
  const EllipticOrbitModel model(body, EllipticOrbit::from_mu_axis(mu, a, e, nu0));
  const InertialSetup is = setup(body, mu, a, e, nu0, Vec3(0.3, -0.5, 0.9));
  const test::InertialSatellite x1 = test::inertial_flow(is.problem, is.x0, T);
  // The anomaly reached, read off the inertial position (unwrapped with the mean motion).
  const Mat3 Q = test::rotation(0.3, 0.7, -0.2, 0.5);
  const double raw = std::atan2(x1.r.dot(Q.col(1)), x1.r.dot(Q.col(0)));
  const double nu_mean = nu0 + model.orbit().mean_motion * T;
  const double nu1 =
      raw + 2 * std::numbers::pi * std::round((nu_mean - raw) / (2 * std::numbers::pi));
  const OrbitState x0 = body_view(is.x0, is.N, body);
  const OrbitState inertial = body_view(x1, is.N, body);
  EXPECT_LT(test::max_distance(test::reference(model, x0, nu0, nu1), inertial), kInertialAgreement);
  const OrbitSplittingStepper s8(composition_table("splitting8"));
  EXPECT_LT(test::max_distance(integrate(s8, model, x0, nu0, nu1, 0.005).state, inertial),
            kInertialAgreement);
  // Kepler's time to the same anomaly: the inertial clock, to the integration's accuracy.
  EXPECT_NEAR(elapsed_time(model.orbit(), nu0, nu1), T, kInertialAgreement * T);
}

// Kepler's time against a Gauss–Kronrod quadrature of dt/dν (relative accuracy ~1e-15 on this
// smooth periodic integrand): 1e-13 relative.
constexpr double kKeplerTime = 1e-13;

TEST(Kepler, ElapsedTimeIsTheIntegralOfTimePerAnomaly) {
  for (double e : {0.0, 0.1, 0.5, 0.9}) {
    const EllipticOrbit o = EllipticOrbit::from_mean_motion(0.8, e, 0.3);
    for (auto [nu1, nu2] : {std::pair{0.3, 2.0}, {-1.0, 3.5}, {2.0, 14.0}, {5.0, -3.0}}) {
      const double q = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
          [&](double nu) { return time_per_anomaly(o, nu); }, nu1, nu2, 15, 1e-15);
      EXPECT_NEAR(elapsed_time(o, nu1, nu2), q, kKeplerTime * std::abs(q)) << e << " " << nu1;
    }
    // A full revolution takes 2π/n; ν(t) inverts t(ν).
    EXPECT_NEAR(elapsed_time(o, 1.0, 1.0 + 2 * std::numbers::pi), 2 * std::numbers::pi / 0.8,
                kKeplerTime);
    for (double t : {0.0, 0.7, 5.0, 31.0, -4.0}) {
      EXPECT_NEAR(elapsed_time(o, 0.3, true_anomaly_at(o, t)), t, kKeplerTime * (1 + std::abs(t)));
    }
  }
}

// Far from t = 0 the mean anomaly is reduced by whole turns before Kepler's equation is solved:
// ν(t + kT) = ν(t) + 2πk up to the rounding of the larger number (|ν| ulps, i.e. 4 eps |ν|
// with the reduction's and the sum's roundings), and a time whose n t is beyond double precision
// (1e17) still gives a finite angle instead of an empty bracket.
constexpr double kTurnsUlps = 4.0;

TEST(Kepler, WholeTurnsAreReducedBeforeTheSolve) {
  for (double e : {0.0, 0.1, 0.6}) {
    const EllipticOrbit o = EllipticOrbit::from_mean_motion(0.8, e, 0.3);
    const double T = 2 * std::numbers::pi / 0.8;
    for (double k : {1.0, 1e3, 1e6}) {
      for (double t : {0.4, 2.0, 6.5}) {
        const double far = true_anomaly_at(o, t + k * T);
        const double want = true_anomaly_at(o, t) + 2 * std::numbers::pi * k;
        // t + kT itself is rounded: its error moves ν by at most σ⁻¹ ulp(t + kT) (rate ≤
        // n(1+e)²/(1−e²)^1.5).
        const double rate = 0.8 * (1 + e) * (1 + e) / std::pow(1 - e * e, 1.5);
        const double tol = kTurnsUlps * std::numeric_limits<double>::epsilon() *
                           (std::abs(want) + rate * (t + k * T));
        EXPECT_NEAR(far, want, tol) << e << " " << k << " " << t;
      }
    }
    EXPECT_TRUE(std::isfinite(true_anomaly_at(o, 1e17))) << e;
  }
}

// A short arc: elapsed_time(ν − δ/2, ν + δ/2) = σ(ν) δ (1 + O(δ²)); with δ = 1e-7 the midpoint
// rule is exact to 1e-14 relative, so the arc must carry full precision (a difference of two
// absolute times would lose ~eps·t/Δt ≈ 1e-9).
constexpr double kShortArc = 1e-13;

TEST(Kepler, ShortArcKeepsRelativePrecision) {
  const EllipticOrbit o = EllipticOrbit::from_mean_motion(0.8, 0.6, 0.0);
  for (double nu : {0.2, 3.0, 1000.0}) {
    const double nu1 = nu - 0.5e-7, nu2 = nu + 0.5e-7;
    const double expected =
        time_per_anomaly(o, 0.5 * (nu1 + nu2)) * (nu2 - nu1);  // exact difference
    EXPECT_NEAR(elapsed_time(o, nu1, nu2), expected, kShortArc * expected);
  }
}

TEST(OrbitInput, BadOrbitsAndBodiesAreRejected) {
  EXPECT_THROW(EllipticOrbit::from_mu_axis(1.0, 1.0, 1.0, 0.0), InputError);
  EXPECT_THROW(EllipticOrbit::from_mu_axis(1.0, 1.0, -0.1, 0.0), InputError);
  EXPECT_THROW(EllipticOrbit::from_mu_axis(-1.0, 1.0, 0.1, 0.0), InputError);
  EXPECT_THROW(EllipticOrbit::from_mu_axis(1.0, 0.0, 0.1, 0.0), InputError);
  EXPECT_THROW(EllipticOrbit::from_mu_axis(1.0, 1.0, 0.1, NAN), InputError);
  EXPECT_THROW(CircularOrbit::from_mu_radius(1.0, -2.0), InputError);
  EXPECT_THROW(CircularOrbit::from_rate(0.0), InputError);
  EXPECT_THROW(CircularOrbit::forced(INFINITY, 1.0), InputError);
  const Body off_centre = Body::from_principal(Vec3(1, 2, 2.5), 1.0, Vec3(0.1, 0, 0));
  EXPECT_THROW(CircularOrbitModel(off_centre, CircularOrbit::from_rate(1.0)), InputError);
  try {
    CircularOrbitModel m(off_centre, CircularOrbit::from_rate(1.0));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("center_of_mass"), std::string::npos);
  }
  const Body body = test::orbit_body();
  OrbitState s = test::tumbling_state(body);
  EXPECT_NO_THROW(check_orbit_state(s, 1e-12));
  s.normal = (s.normal + 1e-6 * s.gamma).normalized();
  EXPECT_THROW(check_orbit_state(s, 1e-9), InputError);
}

TEST(OrbitModel, RelativeStateRoundTrip) {
  const Body body = test::orbit_body();
  const Mat3 F = test::rotation(0.2, -0.9, 0.3, 0.4);
  const Vec3 w_rel(0.1, 0.2, -0.3);
  const OrbitState s = state_from_relative(body, F, w_rel, 0.7);
  EXPECT_LT((orbital_frame(s) - F).cwiseAbs().maxCoeff(), 8 * kOrbitEps);
  EXPECT_LT((relative_omega(body, s, 0.7) - w_rel).cwiseAbs().maxCoeff(), 8 * kOrbitEps);
}

}  // namespace
}  // namespace test_orbit_model
}  // namespace newtop
