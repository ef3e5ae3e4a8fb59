#include "newtop/analysis/lagrange_case.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "newtop/analysis/analytic_quadrature.hpp"
#include "newtop/analysis/lagrange_attitude.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop {
namespace {

// A root of F whose imaginary part is below this (relative) is real: the companion-matrix
// eigenvalues of a double root split by about √ε; Newton polishing then restores full accuracy.
constexpr double kRealRootImag = 1e-6;
// Turning values closer than this are one double root: γ3 is constant (regular precession).
constexpr double kSteadyWidth = 1e-12;
constexpr int kNewtonIterations = 4;

double poly(const std::array<double, 5>& q, double u) {
  return (((q[4] * u + q[3]) * u + q[2]) * u + q[1]) * u + q[0];
}
double dpoly(const std::array<double, 5>& q, double u) {
  return ((4 * q[4] * u + 3 * q[3]) * u + 2 * q[2]) * u + q[1];
}
double d2poly(const std::array<double, 5>& q, double u) {
  return (12 * q[4] * u + 6 * q[3]) * u + 2 * q[2];
}

/// Real roots of F, ascending, from the companion matrix, polished by Newton.
std::vector<double> real_roots(const std::array<double, 5>& q) {
  const double scale =
      std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3]), std::abs(q[4])});
  int d = 4;
  while (d > 0 && std::abs(q[d]) <= 1e-15 * scale) --d;
  std::vector<double> roots;
  if (d == 0) return roots;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(d, d);
  for (int i = 0; i < d; ++i) M(0, i) = -q[d - 1 - i] / q[d];
  for (int i = 1; i < d; ++i) M(i, i - 1) = 1.0;
  const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(M, false).eigenvalues();
  for (const auto& z : ev) {
    if (std::abs(z.imag()) > kRealRootImag * (1.0 + std::abs(z.real()))) continue;
    double u = z.real();
    for (int it = 0; it < kNewtonIterations; ++it) {
      const double df = dpoly(q, u);
      if (df == 0.0) break;
      u -= poly(q, u) / df;
    }
    roots.push_back(u);
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

/// Roots of 4s³ − g2 s − g3 = 0 and the Jacobi form of ℘ on the real axis (A&S 18.9).
void weierstrass(LagrangeCase& s) {
  const double g2 = s.g2, g3 = s.g3;
  auto cubic = [&](double x) { return (4 * x * x - g2) * x - g3; };
  auto polish = [&](double x) {
    for (int it = 0; it < kNewtonIterations; ++it) {
      const double d = 12 * x * x - g2;
      if (d == 0.0) break;
      x -= cubic(x) / d;
    }
    return x;
  };
  const double disc = g2 * g2 * g2 - 27 * g3 * g3;
  s.three_real = disc > 0;
  if (s.three_real) {
    const double rho = std::sqrt(g2 / 12.0);
    const double arg = std::clamp(g3 / (8 * rho * rho * rho), -1.0, 1.0);
    const double th = std::acos(arg);
    double e[3];
    for (int k = 0; k < 3; ++k) {
      e[k] = polish(2 * rho * std::cos((th - 2 * std::numbers::pi * k) / 3));
    }
    std::sort(e, e + 3);
    s.e_low = e[0];
    s.e_span = e[2] - e[0];
    s.modulus = std::sqrt(std::clamp((e[1] - e[0]) / s.e_span, 0.0, 1.0));
    s.scale = std::sqrt(s.e_span);
  } else {
    const double p = -g2 / 4, q = -g3 / 4;
    const double D = std::sqrt(q * q / 4 + p * p * p / 27);
    const double e2 = polish(std::cbrt(-q / 2 + D) + std::cbrt(-q / 2 - D));
    const double H = std::sqrt(3 * e2 * e2 - g2 / 4);
    s.e_low = e2;
    s.e_span = H;
    s.modulus = std::sqrt(std::clamp(0.5 - 3 * e2 / (4 * H), 0.0, 1.0));
    s.scale = 2 * std::sqrt(H);
  }
  const double K = boost::math::ellint_1(s.modulus);
  s.nutation_period = (s.three_real ? 2 * K : 4 * K) / s.scale;
}

/// The argument w of the Jacobi functions with ℘(w / scale) = P (0 ≤ w ≤ half period).
double inverse_wp(const LagrangeCase& s, double P) {
  if (s.three_real) {
    const double sn2 = std::clamp(s.e_span / (P - s.e_low), 0.0, 1.0);
    return boost::math::ellint_1(s.modulus, std::asin(std::sqrt(sn2)));
  }
  const double rho = (P - s.e_low) / s.e_span;
  const double cn = std::clamp((rho - 1) / (rho + 1), -1.0, 1.0);
  return boost::math::ellint_1(s.modulus, std::acos(cn));
}

/// φ̇ = (p γ1 + q γ2)/(1 − γ3²) = (b − β γ3)/(1 − γ3²).
double precession_rate(const LagrangeCase& s, double u) {
  const LagrangeQuartic& Q = s.quartic;
  return (Q.b - Q.beta * u) / (1 - u * u);
}

double psi_rate(const LagrangeCase& s, double u) {
  const LagrangeQuartic& Q = s.quartic;
  return Q.r - (Q.b - Q.beta * u) * u / (1 - u * u);
}

/// γ3 and dγ3/dz at the argument z of ℘.
std::array<double, 2> gamma3_at(const LagrangeCase& s, double z) {
  const double w = s.scale * z;
  double cn = 0, dn = 0;
  const double sn = boost::math::jacobi_elliptic(s.modulus, w, &cn, &dn);
  const double c = s.d2F / 24;
  double num, den, dnum;
  if (s.three_real) {
    num = sn * sn;
    den = (s.e_low - c) * num + s.e_span;
    dnum = 2 * std::pow(s.e_span, 1.5) * cn * dn * sn;
  } else {
    num = 1 - cn;
    den = (s.e_low - c) * num + s.e_span * (1 + cn);
    dnum = 4 * std::pow(s.e_span, 1.5) * sn * dn;
  }
  return {s.u1 + 0.25 * s.dF * num / den, 0.25 * s.dF * dnum / (den * den)};
}

/// Refines z0 by Gauss–Newton on the distance in the phase plane (γ3, γ̇3/Ω): γ3 alone fixes z0
/// only to √ε near a turning point, where γ̇3 (whose derivative γ̈3 = F′(γ3)/2 ≠ 0) fixes it well.
void refine_z0(LagrangeCase& s, double u0, double u_dot0) {
  const double Omega = 2 * std::numbers::pi / s.nutation_period;
  const auto& q = s.quartic.coefficient;
  for (int it = 0; it < kNewtonIterations; ++it) {
    const auto [u, du] = gamma3_at(s, s.z0);
    const double u_dot = s.direction * du, u_ddot = 0.5 * dpoly(q, u);
    const double r1 = u - u0, r2 = (u_dot - u_dot0) / Omega;
    const double j1 = s.direction * u_dot, j2 = s.direction * u_ddot / Omega;  // d/dz
    const double jj = j1 * j1 + j2 * j2;
    if (jj == 0.0) break;
    s.z0 -= (j1 * r1 + j2 * r2) / jj;
  }
}

}  // namespace

bool lagrange_case_holds(const QuadraticModel& model) { return lagrange_holds(model); }

LagrangeQuartic lagrange_quartic(const QuadraticModel& model, const State& x0) {
  const Body& body = model.body;
  const double A = body.A(), C = body.C();
  LagrangeQuartic Q;
  const double h = energy(model, x0);
  Q.r = (x0.m.z() - body.gyrostat().z()) / C;
  Q.E = (2 * h - C * Q.r * Q.r - model.field.lambda_ * A) / A;
  Q.a = 2 * body.mass() * model.field.g * body.center_of_mass().z() / A;
  Q.a1 = model.field.lambda_ * (C - A) / A;
  Q.b = area(x0) / A;
  Q.c = C / A;
  Q.beta = x0.m.z() / A;
  Q.coefficient = {Q.E - Q.b * Q.b, -Q.a + 2 * Q.b * Q.beta, -Q.a1 - Q.E - Q.beta * Q.beta, Q.a,
                   Q.a1};
  return Q;
}

LagrangeCase lagrange_case(const QuadraticModel& model, const State& x0) {
  if (!lagrange_case_holds(model)) {
    throw InputError("body: the Lagrange case needs A = B, x0 = y0 = 0 and k1 = k2 = 0");
  }
  if (!x0.m.allFinite() || !x0.gamma.allFinite()) {
    throw InputError("initial: expected a finite state, found m = " + format_vector(x0.m));
  }
  LagrangeCase s;
  s.initial = x0;
  s.inertia = model.body.inertia();
  s.gyrostat = model.body.gyrostat();
  s.quartic = lagrange_quartic(model, x0);
  s.psi0 = std::atan2(x0.gamma.x(), x0.gamma.y());
  const auto& q = s.quartic.coefficient;
  s.real_roots = real_roots(q);
  const double u0 = x0.gamma.z();
  // The interval of F ≥ 0 that holds u0: consecutive roots with F > 0 between them.
  double lo = u0, hi = u0, best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < s.real_roots.size(); ++i) {
    const double r0 = s.real_roots[i], r1 = s.real_roots[i + 1];
    if (!(poly(q, 0.5 * (r0 + r1)) > 0)) continue;
    const double dist = std::max({r0 - u0, u0 - r1, 0.0});
    if (dist < best) best = dist, lo = r0, hi = r1;
  }
  s.steady = !(hi - lo > kSteadyWidth);
  if (s.steady) {
    s.u1 = s.u2 = u0;
    s.nutation_period = std::numeric_limits<double>::infinity();
    return s;
  }
  // Expand about the turning value nearer to u0, where the inversion of ℘ is well conditioned.
  const bool near_lo = u0 - lo <= hi - u0;
  s.u1 = near_lo ? lo : hi;
  s.u2 = near_lo ? hi : lo;
  s.dF = dpoly(q, s.u1);
  s.d2F = d2poly(q, s.u1);
  const double b0 = q[4], b1 = q[3] / 4, b2 = q[2] / 6, b3 = q[1] / 4, b4 = q[0];
  s.g2 = b0 * b4 - 4 * b1 * b3 + 3 * b2 * b2;
  s.g3 = b0 * b2 * b4 + 2 * b1 * b2 * b3 - b2 * b2 * b2 - b0 * b3 * b3 - b1 * b1 * b4;
  weierstrass(s);
  const double du = u0 - s.u1;
  s.z0 = du == 0.0 ? 0.0 : inverse_wp(s, s.d2F / 24 + s.dF / (4 * du)) / s.scale;
  // γ̇3 = q γ1 − p γ2: moving away from u1 means z increasing.
  const Vec3 w = omega(model.body, x0);
  const double u_dot = w.y() * x0.gamma.x() - w.x() * x0.gamma.y();
  s.direction = u_dot * (s.u2 - s.u1) >= 0 ? 1.0 : -1.0;
  refine_z0(s, u0, u_dot);
  return s;
}

std::array<double, 2> lagrange_gamma3(const LagrangeCase& s, double t) {
  if (s.steady) return {s.u1, 0.0};
  const auto [u, du] = gamma3_at(s, s.z0 + s.direction * t);
  return {u, s.direction * du};
}

Vec3 lagrange_euler_angles(const LagrangeCase& s, double t) {
  const double u = lagrange_gamma3(s, t)[0];
  auto spin_rate = [&](double tau) { return psi_rate(s, lagrange_gamma3(s, tau)[0]); };
  auto prec_rate = [&](double tau) { return precession_rate(s, lagrange_gamma3(s, tau)[0]); };
  const double psi = s.steady ? s.psi0 + spin_rate(0.0) * t
                              : s.psi0 + integrate_periodic(spin_rate, s.nutation_period, t);
  const double phi =
      s.steady ? prec_rate(0.0) * t : integrate_periodic(prec_rate, s.nutation_period, t);
  return {phi, std::acos(std::clamp(u, -1.0, 1.0)), psi};
}

State lagrange_state(const LagrangeCase& s, double t) {
  const auto [u, u_dot] = lagrange_gamma3(s, t);
  auto rate = [&](double tau) { return psi_rate(s, lagrange_gamma3(s, tau)[0]); };
  const double psi =
      s.steady ? s.psi0 + rate(0.0) * t : s.psi0 + integrate_periodic(rate, s.nutation_period, t);
  const double st2 = 1 - u * u, st = std::sqrt(st2);
  const Vec3 gamma(st * std::sin(psi), st * std::cos(psi), u);
  const double S = s.quartic.b - s.quartic.beta * u;  // p γ1 + q γ2
  const double p = (S * gamma.x() - u_dot * gamma.y()) / st2;
  const double q = (S * gamma.y() + u_dot * gamma.x()) / st2;
  const double A = s.inertia.x();
  return {Vec3(A * p + s.gyrostat.x(), A * q + s.gyrostat.y(), s.initial.m.z()), gamma};
}

}  // namespace newtop
