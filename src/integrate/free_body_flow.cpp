#include "newtop/integrate/free_body_flow.hpp"

#include <algorithm>
#include <array>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <limits>

namespace newtop {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// m × ω below this multiple of eps·|m||ω| is a permanent rotation: the rounding of m × ω itself.
constexpr double kPermanentFactor = 8.0;

// Boost.Math promotes double arguments to long double by default, which costs ~7× here; the
// double algorithms are accurate to a few ulps.
using DoublePolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

double rf(double x, double y, double z) { return boost::math::ellint_rf(x, y, z, DoublePolicy()); }
double rj(double x, double y, double z, double p) {
  return boost::math::ellint_rj(x, y, z, p, DoublePolicy());
}

/// Rotation S(l) taking the unit vector l to e_z: S = R_x(θ) R_z(ψ) Q with Q the cyclic permutation
/// that brings `pole` last, l' = Q l = (sinθ sinψ, sinθ cosψ, cosθ).
Mat3 euler_frame(const Vec3& l, int pole) {
  const int a = (pole + 1) % 3, b = (pole + 2) % 3;
  // |l| = 1: the plain root of the sum of squares neither overflows nor underflows (hypot's
  // scaling would cost a fifth of the flow).
  const double st = std::sqrt(l[a] * l[a] + l[b] * l[b]), ct = l[pole];
  const double sp = st > 0 ? l[a] / st : 0.0, cp = st > 0 ? l[b] / st : 1.0;
  // Rows of R_x(θ) R_z(ψ), then columns permuted by Q (column j of the product goes to axis j').
  const double r[3][3] = {{cp, -sp, 0.0}, {ct * sp, ct * cp, -st}, {st * sp, st * cp, ct}};
  Mat3 S;
  for (int i = 0; i < 3; ++i) {
    S(i, a) = r[i][0];
    S(i, b) = r[i][1];
    S(i, pole) = r[i][2];
  }
  return S;
}

/// n s³ R_J(c², d², 1, 1 − n s²)/n-free part: s³ R_J(…) for |φ| ≤ π/2 (c = cos φ ≥ 0).
double third_kind_part(double n, double s, double c, double d) {
  if (s == 0.0) return 0.0;
  return s * s * s * rj(c * c, d * d, 1.0, 1.0 - n * s * s);
}

/// The working frame, the elliptic parameters, sn cn dn at the start and the constants of the
/// precession angle: everything but the complete integral K and the argument u0 (set_argument).
void setup_elliptic(EulerPoinsot& s, const Vec3& m) {
  const Vec3& I = s.inertia;
  std::array<int, 3> order{0, 1, 2};
  if (I[order[0]] > I[order[1]]) std::swap(order[0], order[1]);
  if (I[order[1]] > I[order[2]]) std::swap(order[1], order[2]);
  if (I[order[0]] > I[order[1]]) std::swap(order[0], order[1]);
  const double Imid = I[order[1]];
  // D = L² − 2E I_mid: m circulates about the largest axis when D > 0, the smallest when D < 0.
  double D = 0.0;
  for (int i = 0; i < 3; ++i) D += m[i] * m[i] * (I[i] - Imid) / I[i];
  if (D < 0) std::swap(order[0], order[2]);
  // Signed permutation with det = +1: an odd permutation gets its last row negated.
  const int inversions = (order[0] > order[1]) + (order[0] > order[2]) + (order[1] > order[2]);
  s.frame.setZero();
  for (int r = 0; r < 3; ++r) s.frame(r, order[r]) = 1.0;
  if (inversions % 2 == 1) s.frame(2, order[2]) = -1.0;
  const Vec3 w = s.frame * m;
  const Vec3 J(I[order[0]], I[order[1]], I[order[2]]);
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
  s.complementary = 1.0 - k2;
  s.nu = s3 * (C > B ? 1.0 : -1.0) * std::sqrt((C - B) * D2 / (A * B * C));
  s.amplitude = Vec3(a1, a2, s3 * a3);
  // Start: sn u0 = w2/α2, cn u0 = w1/α1, dn u0 = |w3|/α3 (the last without the cancellation of
  // 1 − k² sn² near the separatrix).
  double sn0 = a2 > 0 ? w[1] / a2 : 0.0, cn0 = a1 > 0 ? w[0] / a1 : 1.0;
  const double norm = std::sqrt(sn0 * sn0 + cn0 * cn0);  // ≈ 1: no hypot needed
  sn0 /= norm, cn0 /= norm;
  const double dn0 = a3 > 0 ? std::abs(w[2]) / a3 : 1.0;
  s.jacobi_start = Vec3(sn0, cn0, dn0);
  // u0 = 2jK + u0r with |u0r| ≤ K: j = 0 for cn0 ≥ 0, otherwise ±1.
  s.half_periods_start = cn0 < 0 ? (sn0 < 0 ? -1 : 1) : 0;
  const double sgn = s.half_periods_start == 0 ? 1.0 : -1.0;
  // The pole of the Euler angles: the working axis that m stays farthest from (least amplitude);
  // L² − m_p² = c (1 − n sn²u).
  const double L2 = w.squaredNorm(), L = std::sqrt(L2);
  int p = 0;
  double c = a3 * a3, n = a3 > 0 ? -(a1 * a1) / (a3 * a3) : 0.0;
  if (a2 < a1 && a2 <= a3) {
    p = 1, c = L2, n = a2 * a2 / L2;
  } else if (a3 < a1 && a3 < a2) {
    p = 2, c = a1 * a1, n = a1 > 0 ? -(a3 * a3) * k2 / (a1 * a1) : 0.0;
  }
  s.pole = order[p];
  double excess = 0.0;  // 2E − L²/I_p
  for (int i = 0; i < 3; ++i) excess += w[i] * w[i] * (1.0 / J[i] - 1.0 / J[p]);
  s.characteristic = n;
  s.mean_rate = L / J[p] + L * excess / c;
  s.third_kind_scale = L * excess * n / (3.0 * c * s.nu);
  s.third_kind_start = third_kind_part(n, sgn * sn0, sgn * cn0, dn0);
}

/// K(k), the period and u0 = F(am u0) by Carlson's R_F, from sn cn dn at the start.
void set_argument(EulerPoinsot& s) {
  const double kc2 = s.complementary;
  s.quarter = kc2 > 0.0 ? rf(0.0, kc2, 1.0) : std::numeric_limits<double>::infinity();
  s.period = 4.0 * s.quarter / std::abs(s.nu);
  const double sn0 = s.jacobi_start[0], cn0 = s.jacobi_start[1], dn0 = s.jacobi_start[2];
  const double f0 = sn0 * rf(cn0 * cn0, dn0 * dn0, 1.0);  // F(φ0r), φ0r = φ0 reduced
  // For cn0 < 0: φ0 = jπ + φ0r with sin φ0r = −sn0 (j = ±1), so u0 = 2jK + F(φ0r).
  s.u0 = s.half_periods_start == 0 ? f0 : 2.0 * s.half_periods_start * s.quarter - f0;
}

/// The free motion from x0 without K and u0 (setup_elliptic); s.permanent when m is constant.
EulerPoinsot euler_poinsot_start(const Body& body, const State& x0) {
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
  s.momentum_norm = x0.m.norm();
  setup_elliptic(s, x0.m);
  s.euler_start = euler_frame(x0.m.normalized(), s.pole);
  return s;
}

}  // namespace

EulerPoinsot euler_poinsot(const Body& body, const State& x0) {
  EulerPoinsot s = euler_poinsot_start(body, x0);
  if (!s.permanent) set_argument(s);
  return s;
}

namespace {

/// sn, cn, dn at u = u_r + 2jK (|u_r| ≤ K), returned for u_r, with j.
struct Reduced {
  double sn, cn, dn;
  int j;
};

Reduced jacobi_reduced(const EulerPoinsot& s, double u) {
  Reduced r{0.0, 1.0, 1.0, 0};
  const double half = 2.0 * s.quarter;
  if (std::isfinite(half)) r.j = static_cast<int>(std::nearbyint(u / half));
  const double ur = std::isfinite(half) ? u - r.j * half : u;
  double dn_boost = 0.0;
  r.sn = boost::math::jacobi_elliptic(s.modulus, ur, &r.cn, &dn_boost, DoublePolicy());
  // Boost's dn in double loses digits near |u_r| = K (3e-12 absolute at K − u_r = 3e-5, k = 0.79,
  // against its long-double value); dn² = k'² + k² cn² is a sum of two non-negative terms, exact
  // to a few ε from the accurate cn.
  const double k2 = s.modulus * s.modulus;
  r.dn = std::sqrt((1.0 - k2) + k2 * r.cn * r.cn);
  return r;
}

/// m(t) from the Jacobi functions, scaled to the invariant |m| = |m(0)|: the amplitudes and the
/// double-precision Jacobi functions carry errors of a few ε that keep their sign while the state
/// changes slowly, and m·γ after the flow is |m(t)|/|m(0)| times m·γ before it (γ(t) is a rotation
/// of γ(0) taking m(0)/|m(0)| to m(t)/|m(t)|), so without the scaling the Casimir m·γ of a
/// splitting drifts like the number of steps instead of performing a random walk.
Vec3 momentum_at(const EulerPoinsot& s, const Reduced& r) {
  const double sign = r.j % 2 == 0 ? 1.0 : -1.0;  // sn, cn change sign every half period
  const Vec3 w(s.amplitude[0] * sign * r.cn, s.amplitude[1] * sign * r.sn, s.amplitude[2] * r.dn);
  return (s.momentum_norm / w.norm()) * (s.frame.transpose() * w);
}

double precession_at(const EulerPoinsot& s, const Reduced& r, double t) {
  const double n = s.characteristic;
  double third = third_kind_part(n, r.sn, r.cn, r.dn) - s.third_kind_start;
  const int dj = r.j - s.half_periods_start;
  if (dj != 0) third += 2.0 * dj * rj(0.0, 1.0 - s.modulus * s.modulus, 1.0, 1.0 - n);
  return s.mean_rate * t + s.third_kind_scale * third;
}

}  // namespace

Vec3 angular_momentum(const EulerPoinsot& s, double t) {
  if (s.permanent) return s.initial.m;
  return momentum_at(s, jacobi_reduced(s, s.u0 + s.nu * t));
}

double precession_angle(const EulerPoinsot& s, double t) {
  if (s.permanent) return 0.0;
  return precession_at(s, jacobi_reduced(s, s.u0 + s.nu * t), t);
}

double precession_rate(const EulerPoinsot& s, const Vec3& m) {
  const int a = (s.pole + 1) % 3, b = (s.pole + 2) % 3;
  const double ma2 = m[a] * m[a], mb2 = m[b] * m[b];
  const double den = ma2 + mb2;
  if (den == 0.0) return 0.0;
  return m.norm() * (ma2 / s.inertia[a] + mb2 / s.inertia[b]) / den;
}

State free_body_state(const EulerPoinsot& s, double t) {
  Mat3 G;
  return free_body_state(s, t, G);
}

namespace {

/// The state at t from sn cn dn at u(t) (the Euler frame of m(t) and the precession about m).
State state_at(const EulerPoinsot& s, const Reduced& r, double t, Mat3& G) {
  const Vec3 m = momentum_at(s, r);
  const Mat3 St = euler_frame(m.normalized(), s.pole);
  const Mat3 Rz(Eigen::AngleAxisd(-precession_at(s, r, t), Vec3::UnitZ()));
  G = St.transpose() * (Rz * s.euler_start);
  return {m, St.transpose() * (Rz * (s.euler_start * s.initial.gamma))};
}

/// The permanent rotation: γ̇ = γ × ω = −ω × γ, a rotation by −|ω| t about ω.
State permanent_state(const EulerPoinsot& s, double t, Mat3& G) {
  const Vec3 w = s.initial.m.cwiseQuotient(s.inertia);
  const double n = w.norm();
  if (n == 0.0) {
    G.setIdentity();
    return s.initial;
  }
  G = Eigen::AngleAxisd(-n * t, w / n).toRotationMatrix();
  return {s.initial.m, G * s.initial.gamma};
}

/// sn cn dn at u0 + v from their values at u0 (s.jacobi_start) and at v (Boost), by the addition
/// theorems (DLMF 22.8.1–3), for |v| < 2K: u0 + v then lies within one half period of u0, so the
/// half periods crossed are told by the sign of cn (am u grows with u; cn changes sign where am u
/// passes π/2 + jπ). Written to r reduced like jacobi_reduced (no K, no u0). Returns false, r
/// unset, where the common denominator 1 − k² sn²u0 sn²v falls below 1/2 (near the separatrix,
/// with sn u0 and sn v near ±1): its cancellation would amplify the rounding of its terms.
bool jacobi_after(const EulerPoinsot& s, double v, Reduced& r) {
  constexpr double kLeastDenominator = 0.5;
  const double k = s.modulus, k2 = k * k;
  double cv = 1.0, dn_boost = 1.0;
  const double sv = boost::math::jacobi_elliptic(k, v, &cv, &dn_boost, DoublePolicy());
  const double dv = std::sqrt(s.complementary + k2 * cv * cv);  // as in jacobi_reduced
  const double s0 = s.jacobi_start[0], c0 = s.jacobi_start[1], d0 = s.jacobi_start[2];
  const double den = 1.0 - k2 * (s0 * s0) * (sv * sv);
  if (!(den >= kLeastDenominator)) return false;
  const double sn = (s0 * cv * dv + sv * c0 * d0) / den;
  const double cn = (c0 * cv - s0 * sv * d0 * dv) / den;
  const bool crossed = (cn < 0) != (c0 < 0);
  r.j = s.half_periods_start + (crossed ? (v > 0 ? 1 : -1) : 0);
  const double sign = r.j % 2 == 0 ? 1.0 : -1.0;
  r.sn = sign * sn;
  r.cn = sign * cn;
  r.dn = std::sqrt(s.complementary + k2 * cn * cn);
  return true;
}

constexpr double kPi = 3.141592653589793;

}  // namespace

State free_body_state(const EulerPoinsot& s, double t, Mat3& G) {
  if (s.permanent) return permanent_state(s, t, G);
  return state_at(s, jacobi_reduced(s, s.u0 + s.nu * t), t, G);
}

Quaternion free_body_attitude(const EulerPoinsot& s, const Quaternion& q0, double t) {
  Mat3 G;
  free_body_state(s, t, G);
  // R(t)ᵀ = G R(0)ᵀ.
  return (q0 * Quaternion(Mat3(G.transpose()))).normalized();
}

Vec3 free_body_euler_angles(const EulerPoinsot& s, double t) {
  const Vec3 l = angular_momentum(s, t).normalized();
  const int a = (s.pole + 1) % 3, b = (s.pole + 2) % 3;
  return {precession_angle(s, t), std::atan2(std::hypot(l[a], l[b]), l[s.pole]),
          std::atan2(l[a], l[b])};
}

Quaternion free_body_pole_frame(const EulerPoinsot& s) {
  const int a = (s.pole + 1) % 3, b = (s.pole + 2) % 3;
  Mat3 Q = Mat3::Zero();
  Q(0, a) = Q(1, b) = Q(2, s.pole) = 1.0;
  return Quaternion(Q);
}

State free_body_flow(const Body& body, const State& x, double h) {
  Mat3 G;
  return free_body_flow(body, x, h, G);
}

State free_body_flow(const Body& body, const State& x, double h, Mat3& rotation) {
  EulerPoinsot s = euler_poinsot_start(body, x);
  if (s.permanent) return permanent_state(s, h, rotation);
  // |ν h| < π ≤ 2K: within a half period of the start, by the addition theorems (no R_F).
  Reduced r;
  if (std::abs(s.nu * h) < kPi && jacobi_after(s, s.nu * h, r)) return state_at(s, r, h, rotation);
  set_argument(s);
  return free_body_state(s, h, rotation);
}

}  // namespace newtop
