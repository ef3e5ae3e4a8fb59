#pragma once
// High-precision references for the exact field (docs/model.md §2), independent of the library's
// formulas: direct point-mass sums, the closed form of a homogeneous rectangular prism (MacMillan's
// antiderivative of 1/r) and the ellipsoid in Carlson's integrals, all evaluated in
// Boost.Multiprecision (50 or 100 significant digits) in the naive form L = γ × ∂V/∂γ. They lose
// the same (R/r)² (prism: (R/r)⁵) digits to cancellation as the double formulas once did, but from
// 50 or 100 digits: enough to check double results to the last bit for R/r ≤ 1e8.

#include <array>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <vector>

#include "newtop/core/types.hpp"

namespace newtop::test {

using Real50 = boost::multiprecision::cpp_bin_float_50;
using Real100 = boost::multiprecision::cpp_bin_float_100;

template <class T>
using V3 = std::array<T, 3>;
template <class T>
using M3 = std::array<V3<T>, 3>;

template <class T>
V3<T> lift(const Vec3& v) {
  return {T(v.x()), T(v.y()), T(v.z())};
}
template <class T>
Vec3 lower(const V3<T>& v) {
  return {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])};
}
template <class T>
Mat3 lower(const M3<T>& m) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = static_cast<double>(m[i][j]);
  return r;
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// V, ∂V/∂γ, L = γ × ∂V/∂γ and ∂²V/∂γ² at a free vector γ (mass model's frame).
template <class T>
struct Reference {
  T potential;
  V3<T> grad_gamma;
  V3<T> moment;
  M3<T> hessian;
  M3<T> moment_jacobian;  ///< ∂L/∂γ = [γ]× ∂²V/∂γ² − [∂V/∂γ]×
};

/// Completes a reference from Φ, ∇Φ and ∇∇Φ at x = −Rγ: V = −μΦ, ∂V/∂γ = μR∇Φ, ∂²V/∂γ² = −μR²∇∇Φ.
template <class T>
Reference<T> from_phi(T mu, T R, const V3<T>& gamma, T phi, const V3<T>& grad, const M3<T>& hess) {
  Reference<T> r;
  r.potential = -mu * phi;
  for (int i = 0; i < 3; ++i) {
    r.grad_gamma[i] = mu * R * grad[i];
    for (int j = 0; j < 3; ++j) r.hessian[i][j] = -mu * R * R * hess[i][j];
  }
  r.moment = cross(gamma, r.grad_gamma);
  for (int j = 0; j < 3; ++j) {
    const V3<T> col = cross(gamma, V3<T>{r.hessian[0][j], r.hessian[1][j], r.hessian[2][j]});
    const V3<T> e{T(j == 0), T(j == 1), T(j == 2)};
    const V3<T> g = cross(r.grad_gamma, e);
    for (int i = 0; i < 3; ++i) r.moment_jacobian[i][j] = col[i] - g[i];
  }
  return r;
}

/// Point masses: Φ = Σ m/|x − ρ|, ∇Φ = Σ m (ρ − x)/d³, ∇∇Φ = Σ m (3 (x − ρ)(x − ρ)ᵀ/d⁵ − 1/d³).
template <class T>
Reference<T> point_masses(const std::vector<double>& m, const std::vector<Vec3>& rho, double mu,
                          double R, const Vec3& gamma) {
  using std::sqrt;
  const V3<T> g = lift<T>(gamma);
  V3<T> x;
  for (int i = 0; i < 3; ++i) x[i] = -T(R) * g[i];
  T phi = 0;
  V3<T> grad{};
  M3<T> hess{};
  for (std::size_t n = 0; n < m.size(); ++n) {
    const V3<T> p = lift<T>(rho[n]);
    const V3<T> d{x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    const T d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], dn = sqrt(d2);
    const T m1 = T(m[n]) / dn, m3 = m1 / d2, m5 = m3 / d2;
    phi += m1;
    for (int i = 0; i < 3; ++i) {
      grad[i] -= m3 * d[i];
      for (int j = 0; j < 3; ++j) hess[i][j] += 3 * m5 * d[i] * d[j] - (i == j ? m3 : T(0));
    }
  }
  return from_phi<T>(T(mu), T(R), g, phi, grad, hess);
}

/// Homogeneous box [lo, hi] of density σ: with (u, v, w) = corner − x, r = |(u, v, w)|,
/// Φ = σ [[[F]]], F = uv ln(w + r) + vw ln(u + r) + wu ln(v + r) − u²/2 atan(vw/(ur)) − …;
/// ∂Φ/∂x_1 = −σ [[[v ln(w + r) + w ln(v + r) − u atan(vw/(ur))]]], ∂²Φ/∂x_1² = −σ
/// [[[atan(vw/(ur))]]], ∂²Φ/∂x_1∂x_2 = σ [[[ln(w + r)]]] (and cyclic), [[[·]]] the alternating sum
/// over the 8 corners.
template <class T>
Reference<T> box(const Vec3& lo, const Vec3& hi, double density, double mu, double R,
                 const Vec3& gamma) {
  using std::atan;
  using std::log;
  using std::sqrt;
  const V3<T> g = lift<T>(gamma);
  T phi = 0;
  V3<T> grad{};
  M3<T> hess{};
  for (int c = 0; c < 8; ++c) {
    V3<T> u;
    int sign = 1;
    for (int i = 0; i < 3; ++i) {
      const bool high = (c >> i) & 1;
      u[i] = T(high ? hi[i] : lo[i]) + T(R) * g[i];
      if (!high) sign = -sign;
    }
    const T r = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const T at = atan(u[j] * u[k] / (u[i] * r));
      phi += sign * (u[i] * u[j] * log(u[k] + r) - u[i] * u[i] / 2 * at);
      grad[i] -= sign * (u[j] * log(u[k] + r) + u[k] * log(u[j] + r) - u[i] * at);
      hess[i][i] -= sign * at;
      hess[i][j] += sign * log(u[k] + r);
      hess[j][i] += sign * log(u[k] + r);
    }
  }
  const T s = T(density);
  for (int i = 0; i < 3; ++i) {
    grad[i] *= s;
    for (int j = 0; j < 3; ++j) hess[i][j] *= s;
  }
  return from_phi<T>(T(mu), T(R), g, s * phi, grad, hess);
}

/// Homogeneous ellipsoid (semi-axes a along the frame's axes, centre c) outside: λ the root of
/// Σ u_i²/(a_i² + λ) = 1 by bisection, q = a² + λ, k = πσabc,
/// Φ = k (2 R_F(q) − ⅔ Σ u_i² R_D(q_j, q_k, q_i)), ∇Φ_i = −(4/3) k u_i R_D(q_j, q_k, q_i),
/// ∇∇Φ = −(4/3) k diag(R_D) + 4k u_i u_j / (q_i q_j √(q1 q2 q3) Σ u_l²/q_l²).
template <class T>
Reference<T> ellipsoid(const Vec3& a, const Vec3& center, double density, double mu, double R,
                       const Vec3& gamma) {
  using boost::math::ellint_rd;
  using boost::math::ellint_rf;
  using std::sqrt;
  const V3<T> g = lift<T>(gamma);
  V3<T> u, a2;
  for (int i = 0; i < 3; ++i) {
    u[i] = -T(R) * g[i] - T(center[i]);
    a2[i] = T(a[i]) * T(a[i]);
  }
  auto f = [&](const T& l) {
    T s = 0;
    for (int i = 0; i < 3; ++i) s += u[i] * u[i] / (a2[i] + l);
    return s - 1;
  };
  T lo = 0, hi = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  for (int it = 0; it < 400; ++it) {
    const T mid = (lo + hi) / 2;
    (f(mid) > 0 ? lo : hi) = mid;
  }
  const T lambda = (lo + hi) / 2;
  V3<T> q, rd;
  for (int i = 0; i < 3; ++i) q[i] = a2[i] + lambda;
  for (int i = 0; i < 3; ++i) rd[i] = ellint_rd(q[(i + 1) % 3], q[(i + 2) % 3], q[i]);
  const T k = boost::math::constants::pi<T>() * T(density) * T(a[0]) * T(a[1]) * T(a[2]);
  T phi = 2 * ellint_rf(q[0], q[1], q[2]), S = 0;
  V3<T> grad;
  for (int i = 0; i < 3; ++i) {
    phi -= T(2) / 3 * u[i] * u[i] * rd[i];
    grad[i] = -T(4) / 3 * k * u[i] * rd[i];
    S += u[i] * u[i] / (q[i] * q[i]);
  }
  const T sq = sqrt(q[0] * q[1] * q[2]);
  M3<T> hess;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      hess[i][j] =
          4 * k * u[i] * u[j] / (q[i] * q[j] * sq * S) - (i == j ? T(4) / 3 * k * rd[i] : T(0));
  return from_phi<T>(T(mu), T(R), g, k * phi, grad, hess);
}

}  // namespace newtop::test
