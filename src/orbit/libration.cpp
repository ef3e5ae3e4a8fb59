// Beletsky's equation and its variational equation (docs/orbit.md §4, §9), integrated together by
// Fehlberg 7(8) in the true anomaly.

#include "newtop/orbit/libration.hpp"

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>

namespace newtop {

PitchProblem pitch_problem(double eccentricity, double k) {
  if (!(eccentricity >= 0.0 && eccentricity < 1.0)) {
    throw InputError("eccentricity: expected 0 <= e < 1, found " + format_number(eccentricity));
  }
  if (!std::isfinite(k))
    throw InputError("k: expected a finite (B - A)/C, found " + format_number(k));
  return {eccentricity, k};
}

PitchProblem pitch_problem(const Body& body, const EllipticOrbit& orbit) {
  check_orbit_body(body);
  if (body.gyrostat() != Vec3::Zero()) {
    throw InputError(
        "gyrostat: expected none for the planar pitch motion (Beletsky's equation), "
        "found " +
        format_vector(body.gyrostat()));
  }
  const Vec3& I = body.inertia();
  return pitch_problem(orbit.eccentricity, (I.y() - I.x()) / I.z());
}

PitchFrame pitch_frame(const Body& body, const OrbitState& s) {
  Eigen::Index a = 2;
  s.normal.cwiseAbs().maxCoeff(&a);
  const int ax = static_cast<int>(a);
  const double sign = s.normal[ax] < 0 ? -1.0 : 1.0;
  Mat3 P = Mat3::Zero();
  P(0, (ax + 1) % 3) = 1.0;
  P(1, (ax + 2) % 3) = sign;
  P(2, ax) = sign;
  const Vec3 I = (P * body.inertia()).cwiseAbs();
  const Body turned =
      Body::from_principal(I, body.mass(), P * body.center_of_mass(), P * body.gyrostat());
  return {turned, {P * s.m, P * s.gamma, P * s.normal}, ax};
}

Vec2 pitch_state(const Body& body, const EllipticOrbit& orbit, const OrbitState& s, double nu,
                 double tolerance) {
  const Vec3 w = omega(body, s);
  const double scale = std::max(1.0, w.norm());
  if ((s.normal - Vec3::UnitZ()).norm() > tolerance || std::abs(s.gamma.z()) > tolerance ||
      std::abs(w.x()) > tolerance * scale || std::abs(w.y()) > tolerance * scale) {
    throw InputError(
        "initial: expected the planar pitch motion (normal = [0, 0, 1], gamma in the "
        "body xy plane, omega along z), found normal = " +
        format_vector(s.normal) + ", gamma = " + format_vector(s.gamma) +
        ", omega = " + format_vector(w));
  }
  return {std::atan2(-s.gamma.y(), s.gamma.x()), w.z() / anomaly_rate(orbit, nu) - 1};
}

Vec2 beletsky_rhs(const PitchProblem& p, const Vec2& x, double nu) {
  const double e = p.eccentricity;
  return {x[1], (2 * e * std::sin(nu) * (x[1] + 1) - 3 * p.k * std::sin(x[0]) * std::cos(x[0])) /
                    (1 + e * std::cos(nu))};
}

Mat2 beletsky_jacobian(const PitchProblem& p, const Vec2& x, double nu) {
  const double e = p.eccentricity, d = 1 + e * std::cos(nu);
  Mat2 a;
  a << 0.0, 1.0, -3 * p.k * std::cos(2 * x[0]) / d, 2 * e * std::sin(nu) / d;
  return a;
}

namespace {

namespace ode = boost::numeric::odeint;

template <class S, class F>
void integrate(F f, S& s, double nu0, double nu1) {
  if (nu1 == nu0) return;
  const double h = nu1 > nu0 ? 1e-2 : -1e-2;
  ode::integrate_adaptive(
      ode::make_controlled<ode::runge_kutta_fehlberg78<S>>(kPitchTolerance, kPitchTolerance), f, s,
      nu0, nu1, h);
}

}  // namespace

Vec2 pitch_advance(const PitchProblem& p, const Vec2& x0, double nu0, double nu1) {
  std::array<double, 2> s{x0[0], x0[1]};
  integrate(
      [&p](const std::array<double, 2>& y, std::array<double, 2>& d, double nu) {
        const Vec2 f = beletsky_rhs(p, Vec2(y[0], y[1]), nu);
        d = {f[0], f[1]};
      },
      s, nu0, nu1);
  return {s[0], s[1]};
}

PitchFlow pitch_flow(const PitchProblem& p, const Vec2& x0, double nu0, double nu1) {
  // s = (θ, θ′, Φ column-major): Φ′ = A(ν, θ) Φ, Φ(ν0) = I.
  std::array<double, 6> s{x0[0], x0[1], 1.0, 0.0, 0.0, 1.0};
  integrate(
      [&p](const std::array<double, 6>& y, std::array<double, 6>& d, double nu) {
        const Vec2 x(y[0], y[1]);
        const Vec2 f = beletsky_rhs(p, x, nu);
        const Mat2 a = beletsky_jacobian(p, x, nu);
        const Mat2 dphi = a * Eigen::Map<const Mat2>(y.data() + 2);
        d = {f[0], f[1], dphi(0, 0), dphi(1, 0), dphi(0, 1), dphi(1, 1)};
      },
      s, nu0, nu1);
  return {Vec2(s[0], s[1]), Eigen::Map<const Mat2>(s.data() + 2)};
}

double liouville_determinant(double eccentricity, double nu0, double nu1) {
  const double r = (1 + eccentricity * std::cos(nu0)) / (1 + eccentricity * std::cos(nu1));
  return r * r;
}

}  // namespace newtop
