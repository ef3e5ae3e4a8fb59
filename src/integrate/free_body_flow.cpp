#include "newtop/integrate/free_body_flow.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <limits>
#include <numeric>

namespace newtop {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// m × ω below this multiple of eps·|m||ω| is a permanent rotation: the rounding of m × ω itself.
constexpr double kPermanentFactor = 8.0;
// Gauss–Kronrod's error estimate |K15 − G7| bounds the 7-point Gauss error; the 15-point Kronrod
// result it returns is far more accurate (its error is roughly the square of the estimate, in
// relative terms), so asking 1e-10 of the estimate gives an angle correct to a few ulps.
constexpr double kQuadratureTolerance = 1e-10;
constexpr unsigned kQuadratureDepth = 15;
// The rate is periodic and analytic over one period, where the trapezoidal rule converges
// geometrically: double the points until two estimates agree to a few ulps.
constexpr double kTrapezoidTolerance = 4 * kEps;
constexpr int kTrapezoidMaxPoints = 1 << 14;

/// Signed permutation (det = +1) whose rows pick the body axes in the order `order`.
Mat3 permutation(const std::array<int, 3>& order) {
  Mat3 P = Mat3::Zero();
  for (int r = 0; r < 3; ++r) P(r, order[r]) = 1.0;
  if (P.determinant() < 0) P.row(2) *= -1.0;
  return P;
}

/// Rotation S(l) taking the unit vector l to e_z: S = R_x(θ) R_z(ψ) Q with Q the cyclic permutation
/// that brings `pole` last, l' = Q l = (sinθ sinψ, sinθ cosψ, cosθ).
Mat3 euler_frame(const Vec3& l, int pole) {
  const int a = (pole + 1) % 3, b = (pole + 2) % 3;
  Mat3 Q = Mat3::Zero();
  Q(0, a) = Q(1, b) = Q(2, pole) = 1.0;
  const double st = std::hypot(l[a], l[b]), ct = l[pole];
  const double sp = st > 0 ? l[a] / st : 0.0, cp = st > 0 ? l[b] / st : 1.0;
  Mat3 Rz, Rx;
  Rz << cp, -sp, 0, sp, cp, 0, 0, 0, 1;
  Rx << 1, 0, 0, 0, ct, -st, 0, st, ct;
  return Rx * Rz * Q;
}

/// dφ/dt = |m| (m_a²/I_a + m_b²/I_b)/(m_a² + m_b²), (a, b, pole) cyclic.
double precession_rate(const EulerPoinsot& s, const Vec3& m) {
  const int a = (s.pole + 1) % 3, b = (s.pole + 2) % 3;
  const double ma2 = m[a] * m[a], mb2 = m[b] * m[b];
  const double den = ma2 + mb2;
  if (den == 0.0) return 0.0;
  return m.norm() * (ma2 / s.inertia[a] + mb2 / s.inertia[b]) / den;
}

double integrate_rate(const EulerPoinsot& s, double t0, double t1) {
  if (t0 == t1) return 0.0;
  auto f = [&](double t) { return precession_rate(s, angular_momentum(s, t)); };
  return boost::math::quadrature::gauss_kronrod<double, 15>::integrate(f, t0, t1, kQuadratureDepth,
                                                                       kQuadratureTolerance);
}

/// ∫ over one period of the periodic rate by the trapezoidal rule, points doubled to convergence.
double integrate_period(const EulerPoinsot& s) {
  auto f = [&](double t) { return precession_rate(s, angular_momentum(s, t)); };
  int n = 16;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += f(s.period * i / n);
  double estimate = sum * s.period / n;
  while (n < kTrapezoidMaxPoints) {
    for (int i = 0; i < n; ++i) sum += f(s.period * (2 * i + 1) / (2 * n));
    n *= 2;
    const double next = sum * s.period / n;
    const bool converged = std::abs(next - estimate) <= kTrapezoidTolerance * std::abs(next);
    estimate = next;
    if (converged) break;
  }
  return estimate;
}

void setup_elliptic(EulerPoinsot& s, const Vec3& m) {
  const Vec3& I = s.inertia;
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return I[i] < I[j]; });
  const double Imid = I[order[1]];
  // D = L² − 2E I_mid: m circulates about the largest axis when D > 0, the smallest when D < 0.
  double D = 0.0;
  for (int i = 0; i < 3; ++i) D += m[i] * m[i] * (I[i] - Imid) / I[i];
  if (D < 0) std::swap(order[0], order[2]);
  s.frame = permutation(order);
  const Vec3 w = s.frame * m;
  const Vec3 J = (s.frame.cwiseAbs() * I);
  s.moments = J;
  const double A = J[0], B = J[1], C = J[2];
  // 2EC − L² and L² − 2EA written as sums of terms of one sign (no cancellation).
  const double D1 = w[0] * w[0] * (C - A) / A + w[1] * w[1] * (C - B) / B;
  const double D2 = w[1] * w[1] * (B - A) / B + w[2] * w[2] * (C - A) / C;
  const double a1 = std::sqrt(w[0] * w[0] + w[1] * w[1] * A * (C - B) / (B * (C - A)));
  const double a2 = std::sqrt(w[1] * w[1] + w[0] * w[0] * B * (C - A) / (A * (C - B)));
  const double a3 = std::sqrt(w[2] * w[2] + w[1] * w[1] * C * (B - A) / (B * (C - A)));
  const double s3 = w[2] < 0 ? -1.0 : 1.0;
  const double k2 = std::clamp((B - A) / (C - B) * D1 / D2, 0.0, 1.0);
  s.modulus = std::sqrt(k2);
  const double nu0 = std::sqrt((C - B) * D2 / (A * B * C));
  s.nu = s3 * (C > B ? 1.0 : -1.0) * nu0;
  s.amplitude = Vec3(a1, a2, s3 * a3);
  const double amp = std::atan2(w[1] / a2, w[0] / a1);
  s.u0 = boost::math::ellint_1(s.modulus, amp);
  s.period = s.modulus < 1.0 ? 4.0 * boost::math::ellint_1(s.modulus) / std::abs(s.nu)
                             : std::numeric_limits<double>::infinity();
  // The pole of the Euler angles: the body axis that m stays farthest from.
  const Vec3 bound = s.frame.cwiseAbs().transpose() * Vec3(a1, a2, a3);
  Eigen::Index pole = 0;
  bound.minCoeff(&pole);
  s.pole = static_cast<int>(pole);
}

}  // namespace

EulerPoinsot euler_poinsot(const Body& body, const State& x0) {
  if (!body.gyrostat().isZero(0.0)) {
    throw InputError("gyrostat: the Euler–Poinsot solution needs k = 0, found k = " +
                     format_vector(body.gyrostat()));
  }
  if (!x0.m.allFinite() || !x0.gamma.allFinite()) {
    throw InputError("initial: expected a finite state, found m = " + format_vector(x0.m) +
                     ", gamma = " + format_vector(x0.gamma));
  }
  EulerPoinsot s;
  s.inertia = body.inertia();
  s.initial = x0;
  const Vec3 w = x0.m.cwiseQuotient(s.inertia);
  s.permanent =
      x0.m.cross(w).norm() <= kPermanentFactor * kEps * x0.m.norm() * w.norm() || x0.m.isZero(0.0);
  if (s.permanent) {
    s.period = std::numeric_limits<double>::infinity();
    return s;
  }
  setup_elliptic(s, x0.m);
  return s;
}

Vec3 angular_momentum(const EulerPoinsot& s, double t) {
  if (s.permanent) return s.initial.m;
  double cn = 0.0, dn = 0.0;
  const double sn = boost::math::jacobi_elliptic(s.modulus, s.u0 + s.nu * t, &cn, &dn);
  const Vec3 w(s.amplitude[0] * cn, s.amplitude[1] * sn, s.amplitude[2] * dn);
  return s.frame.transpose() * w;
}

double precession_angle(const EulerPoinsot& s, double t) {
  if (s.permanent) return 0.0;
  if (!std::isfinite(s.period) || std::abs(t) < s.period) return integrate_rate(s, 0.0, t);
  const double n = std::trunc(t / s.period);
  return n * integrate_period(s) + integrate_rate(s, n * s.period, t);
}

State free_body_state(const EulerPoinsot& s, double t) {
  if (s.permanent) {
    const Vec3 w = s.initial.m.cwiseQuotient(s.inertia);
    const double n = w.norm();
    if (n == 0.0) return s.initial;
    // γ̇ = γ × ω = −ω × γ: a rotation by −|ω| t about ω.
    const Eigen::AngleAxisd R(-n * t, w / n);
    return {s.initial.m, R * s.initial.gamma};
  }
  const Vec3 m = angular_momentum(s, t);
  const Mat3 S0 = euler_frame(s.initial.m.normalized(), s.pole);
  const Mat3 St = euler_frame(m.normalized(), s.pole);
  const Mat3 Rz(Eigen::AngleAxisd(-precession_angle(s, t), Vec3::UnitZ()));
  return {m, St.transpose() * (Rz * (S0 * s.initial.gamma))};
}

}  // namespace newtop

namespace newtop {

State free_body_flow(const Body& body, const State& x, double h) {
  return free_body_state(euler_poinsot(body, x), h);
}

FreeBodySplittingStepper::FreeBodySplittingStepper(const CompositionTable& table)
    : order_(table.order) {
  auto push = [&](bool kick, double fraction) {
    if (!program_.empty() && program_.back().first == kick) {
      program_.back().second += fraction;
    } else {
      program_.emplace_back(kick, fraction);
    }
  };
  for (double c : table.gamma) {
    push(true, 0.5 * c);
    push(false, c);
    push(true, 0.5 * c);
  }
}

}  // namespace newtop
