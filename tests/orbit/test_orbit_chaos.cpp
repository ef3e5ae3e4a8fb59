// Chaos indicators on an orbit (docs/orbit.md §13): the tangent map of the variational equations
// against finite differences of the flow, the spectrum's ± pairing (the Jacobi integral makes the
// circular-orbit flow Hamiltonian on the leaf), MEGNO → 2 on a stable libration and growing on a
// chaotic tumble, and the elliptic case at e = 0 against the circular one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_stability.hpp"
#include "orbit_problems.hpp"

namespace newtop::test {
namespace test_orbit_chaos {
namespace {

MethodSettings pair(const char* name, double tol) {
  MethodSettings m;
  m.name = name;
  m.abs_tol = m.rel_tol = tol;
  return m;
}

/// The body of the Lagrange-region tests: least moment along the radius (x), largest along the
/// orbit normal (z); no rotor.
Body lagrange_body() { return Body::from_principal(Vec3(1.0, 1.6, 2.1), 1.0, Vec3::Zero()); }

/// A start off the stable relative equilibrium γ = x, n = z, at rest in the orbital frame: 0.3
/// rad in pitch, 0.05 in roll and yaw (a libration on a torus).
OrbitState libration_start(const CircularOrbitModel& model) {
  const Mat3 S = (Eigen::AngleAxisd(0.3, Vec3::UnitZ()) * Eigen::AngleAxisd(0.05, Vec3::UnitY()) *
                  Eigen::AngleAxisd(0.05, Vec3::UnitX()))
                     .toRotationMatrix();
  return relative_rest_state(model, S.transpose().col(0), S.transpose().col(2));
}

/// A tumble with ω of the order of the orbit rate about every axis: chaotic.
OrbitState chaotic_start(const Body& body) { return tumbling_state(body, Vec3(0.3, -1.2, 0.9)); }

/// Central differences of the flow, column j: (x(b; x0 + ε e_j) − x(b; x0 − ε e_j)) / 2ε.
template <class M>
Eigen::Matrix<double, 9, 9> finite_difference_map(const M& model, const OrbitState& x0, double a,
                                                  double b, double eps) {
  Eigen::Matrix<double, 9, 9> D;
  auto pack = [](const OrbitState& s) {
    Eigen::Matrix<double, 9, 1> v;
    v << s.m, s.gamma, s.normal;
    return v;
  };
  auto unpack = [](const Eigen::Matrix<double, 9, 1>& v) {
    return OrbitState{v.segment<3>(0), v.segment<3>(3), v.segment<3>(6)};
  };
  for (int j = 0; j < 9; ++j) {
    Eigen::Matrix<double, 9, 1> e = Eigen::Matrix<double, 9, 1>::Zero();
    e[j] = eps;
    const auto plus = pack(reference(model, unpack(pack(x0) + e), a, b, 1e-14));
    const auto minus = pack(reference(model, unpack(pack(x0) - e), a, b, 1e-14));
    D.col(j) = (plus - minus) / (2 * eps);
  }
  return D;
}

// Central differences at ε = 1e-5 err by ε²|x‴|/6 ≈ 2e-11 (|x‴| = O(1) here) and by the runs'
// own errors over 2ε: a few times the tolerance 1e-14 amplified by |Φ| ≈ 10, over 2e-5: ≈ 1e-8.
constexpr double kFiniteDifferenceTolerance = 1e-7;

TEST(OrbitChaos, TangentMapIsTheDerivativeOfTheCircularFlow) {
  const CircularOrbitModel model(orbit_body(), CircularOrbit::from_rate(1.0));
  const OrbitState x0 = tumbling_state(model.body());
  const auto phi = orbit_tangent_map(pair("rkf78", 1e-13), model, x0, 0.0, 3.0);
  const auto fd = finite_difference_map(model, x0, 0.0, 3.0, 1e-5);
  ASSERT_TRUE(phi.allFinite());
  EXPECT_LT((phi - fd).cwiseAbs().maxCoeff(), kFiniteDifferenceTolerance * phi.norm());
}

TEST(OrbitChaos, TangentMapIsTheDerivativeOfTheEllipticFlow) {
  const EllipticOrbitModel model(orbit_body(), EllipticOrbit::from_mean_motion(1.0, 0.3, 0.4));
  const OrbitState x0 = tumbling_state(model.body());
  const auto phi = orbit_tangent_map(pair("dop853", 1e-13), model, x0, 0.4, 3.4);
  const auto fd = finite_difference_map(model, x0, 0.4, 3.4, 1e-5);
  ASSERT_TRUE(phi.allFinite());
  EXPECT_LT((phi - fd).cwiseAbs().maxCoeff(), kFiniteDifferenceTolerance * phi.norm());
}

OrbitChaosSettings chaos_settings(const char* method, double t1, bool spectrum) {
  OrbitChaosSettings s;
  s.method = pair(method, 1e-11);
  s.t1 = t1;
  s.spectrum = spectrum;
  return s;
}

// Over a time T the finite-time exponents of a symplectic flow pair up to O(1/T): the QR
// measures volumes in the Euclidean metric of R⁹, which differs from the symplectic one on the
// leaf by a factor bounded along the orbit; ln of it, over T. With |x| = O(1) that factor is a
// few units: 5/T.
constexpr double kPairingConstant = 5.0;

TEST(OrbitChaos, SpectrumComesInPlusMinusPairsOnACircularOrbit) {
  const CircularOrbitModel model(lagrange_body(), CircularOrbit::from_rate(1.0));
  const double T = 2000.0;
  const OrbitChaosResult r =
      orbit_chaos(model, chaotic_start(model.body()), chaos_settings("rkf78", T, true));
  ASSERT_EQ(r.outcome.status, Status::finished);
  ASSERT_TRUE(r.indicators.spectrum.has_value());
  std::array<double, 6> s = *r.indicators.spectrum;
  std::sort(s.begin(), s.end());
  EXPECT_GT(s[5], 20 * kPairingConstant / T) << "not chaotic: the pairing would be trivial";
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(std::abs(s[i] + s[5 - i]), kPairingConstant / T) << i;
  }
  EXPECT_GT(s[4], 10 * kPairingConstant / T) << "a second positive exponent to pair";
  // The pair of the flow and of the Jacobi integral's gradient: zero. Along them the vectors grow
  // at most linearly (by shear), so their finite-time exponents are ln(cT)/T: (ln T + 1)/T.
  EXPECT_LT(std::abs(s[2]), (std::log(T) + 1.0) / T);
  EXPECT_LT(std::abs(s[3]), (std::log(T) + 1.0) / T);
  EXPECT_NEAR(r.indicators.lyapunov_max, s[5], 0.2 * s[5]);
}

// MEGNO of a quasi-periodic orbit tends to 2 from below as 2 − O(1/t) (Cincotta & Simó 2000: |δ|
// grows linearly, a + bt, by the shear of the torus; the offset a/b is the time the shear takes
// to dominate, a few hundred time units for a libration of 0.3 rad). Measured 1.73, 1.90 at
// t = 2500, 10000 for a planar pitch libration; 0.1 at t = 10⁴ (without the shear, an isochronous
// libration, ⟨Y⟩ → 0 instead; a chaotic one grows without bound).
constexpr double kMegnoRegularTolerance = 0.1;

TEST(OrbitChaos, MegnoTendsToTwoOnAStableLibration) {
  const CircularOrbitModel model(lagrange_body(), CircularOrbit::from_rate(1.0));
  const OrbitState x0 = libration_start(model);
  const OrbitState rest = relative_rest_state(model, Vec3::UnitX(), Vec3::UnitZ());
  ASSERT_EQ(relative_equilibrium_stability(model, rest).verdict, OrbitStability::lyapunov);
  const OrbitChaosResult r = orbit_chaos(model, x0, chaos_settings("dop853", 10000.0, false));
  ASSERT_EQ(r.outcome.status, Status::finished);
  EXPECT_NEAR(r.indicators.megno, 2.0, kMegnoRegularTolerance);
}

// On a chaotic orbit ln|δ| ≈ λ s, so Y(t) ≈ λt and ⟨Y⟩ ≈ λt/2 (Cincotta & Simó 2000), with λ the
// finite-time exponent of the same vector; the fluctuations of ln|δ| about λs spoil it by their
// ratio to λt (measured 12 % at t = 2000): 25 %.
constexpr double kMegnoChaoticRelative = 0.25;

TEST(OrbitChaos, MegnoGrowsOnAChaoticTumble) {
  const CircularOrbitModel model(lagrange_body(), CircularOrbit::from_rate(1.0));
  const OrbitState x0 = chaotic_start(model.body());
  const OrbitChaosResult a = orbit_chaos(model, x0, chaos_settings("rkf78", 500.0, false));
  const OrbitChaosResult b = orbit_chaos(model, x0, chaos_settings("rkf78", 2000.0, false));
  // Far above 2 and growing with t (measured 41 and 91).
  EXPECT_GT(a.indicators.megno, 20.0);
  EXPECT_GT(b.indicators.megno, 1.5 * a.indicators.megno);
  const double half_lambda_t = 0.5 * b.indicators.lyapunov_max * 2000.0;
  EXPECT_NEAR(b.indicators.megno, half_lambda_t, kMegnoChaoticRelative * half_lambda_t);
}

// e = 0: ν = ω0 t and the elliptic equations are the circular ones over ω0; the two runs take
// different steps, so λ_max agrees to the tolerance's effect on a finite-time exponent (its
// tangent vector is sensitive on a chaotic orbit over a short run): 1e-6 relative.
constexpr double kZeroEccentricityTolerance = 1e-6;

TEST(OrbitChaos, EllipticAtZeroEccentricityIsTheCircularCase) {
  const Body body = lagrange_body();
  const CircularOrbitModel circular(body, CircularOrbit::from_rate(0.5));
  const EllipticOrbitModel elliptic(body, EllipticOrbit::from_mean_motion(0.5, 0.0, 0.0));
  const OrbitState x0 = libration_start(circular);
  OrbitChaosSettings s = chaos_settings("rkf78", 20.0, false);
  s.method = pair("rkf78", 1e-14);
  const OrbitChaosResult c = orbit_chaos(circular, x0, s);
  const OrbitChaosResult e = orbit_chaos(elliptic, x0, s);
  EXPECT_NEAR(e.t, 20.0, 1e-12);
  EXPECT_NEAR(e.indicators.lyapunov_max, c.indicators.lyapunov_max,
              kZeroEccentricityTolerance * std::abs(c.indicators.lyapunov_max));
  EXPECT_NEAR(e.indicators.megno, c.indicators.megno,
              kZeroEccentricityTolerance * std::abs(c.indicators.megno));
}

TEST(OrbitChaos, RefusesASplittingAndABadSpan) {
  const CircularOrbitModel model(lagrange_body(), CircularOrbit::from_rate(1.0));
  OrbitChaosSettings s = chaos_settings("rkf78", 10.0, false);
  s.method.name = "splitting4";
  s.method.step = 0.1;
  EXPECT_THROW(orbit_chaos(model, libration_start(model), s), InputError);
  s = chaos_settings("rkf78", -1.0, false);
  EXPECT_THROW(orbit_chaos(model, libration_start(model), s), InputError);
}

// dop853 on the orbit: the same solution as Fehlberg 7(8), both near round-off.
constexpr double kPairAgreement = 1e-10;

TEST(OrbitChaos, Dop853RunsTheOrbitAsFehlberg) {
  const CircularOrbitModel model(orbit_body(), CircularOrbit::from_rate(1.0));
  const OrbitState x0 = tumbling_state(model.body());
  const OrbitOutcome a = run_orbit_method(pair("dop853", 1e-13), model, x0, 0.0, 10.0, 1'000'000);
  const OrbitOutcome b = run_orbit_method(pair("rkf78", 1e-13), model, x0, 0.0, 10.0, 1'000'000);
  ASSERT_EQ(a.status, Status::finished);
  EXPECT_LT(max_distance(a.state, b.state), kPairAgreement);
}

}  // namespace
}  // namespace test_orbit_chaos
}  // namespace newtop::test
