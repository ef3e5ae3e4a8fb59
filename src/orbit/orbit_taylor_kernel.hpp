#pragma once
// The kernels of the orbit's Taylor ensemble (orbit_taylor_ensemble.hpp; private to src/orbit):
// orbit_taylor.cpp's recurrences of (m, γ, n), one trajectory per lane of a vector of L doubles,
// in structure-of-arrays form. Each lane does the operations of orbit_taylor_expand in their order
// (Eigen's cross product a × b, component c: a_{c+1} b_{c+2} − a_{c+2} b_{c+1}; the sums from zero,
// j = 0..k; scalars times vectors), with no fused multiply-add (the files that include this are
// compiled with -ffp-contract=off, as orbit_taylor.cpp is): the same bits as the scalar run.
//
// Layouts, for L lanes: the constants of a lane at consts[q L + l] (OrbitLaneRow); a state
// (m, γ, n) at x[c L + l], c = 0..8; the coefficient k of the series at series[(9 k + c) L + l].

#include <array>
#include <cstddef>
#include <cstring>

namespace newtop::detail {

/// The rows of an orbit ensemble's constants, a lane each: the moments of inertia and the
/// gyrostatic moment; on a circular orbit ω0 and λ; on an ellipse e, (1 − e²)^{3/2}/n,
/// 3n/(1 − e²)^{3/2} and cos ν, sin ν of the lane's anomaly.
enum OrbitLaneRow : int {
  kOrbitInertia = 0,
  kOrbitGyrostat = 3,
  kOrbitRate = 6,
  kOrbitLambda = 7,
  kOrbitEccentricity = 6,
  kOrbitSigma = 7,
  kOrbitSigmaLambda = 8,
  kOrbitCos = 9,
  kOrbitSin = 10,
  kOrbitLaneRows = 11
};

/// One kernel's entry points, for an instruction set.
struct OrbitTaylorLaneKernel {
  int lanes;
  void (*expand_circular)(const double* consts, const double* x, int order, double* series);
  void (*expand_elliptic)(const double* consts, const double* x, int order, double* series);
  /// The coefficients 0..order of one tangent vector per lane (v, the layout of a state) along
  /// the state's series (orbit_taylor_tangent.cpp's recurrences).
  void (*expand_tangent_circular)(const double* consts, const double* series, const double* v,
                                  int order, double* tangent);
  void (*expand_tangent_elliptic)(const double* consts, const double* series, const double* v,
                                  int order, double* tangent);
};

OrbitTaylorLaneKernel orbit_taylor_lane_kernel_portable();
#if defined(__x86_64__) && defined(__GNUC__)
OrbitTaylorLaneKernel orbit_taylor_lane_kernel_avx2();
OrbitTaylorLaneKernel orbit_taylor_lane_kernel_avx512();
#endif

namespace orbit_taylor_simd {

inline constexpr int K = 31;  // OrbitTaylorSeries::kMaxOrder + 1 (orbit_taylor_ensemble.cpp checks)

template <class V>
[[gnu::always_inline]] inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
[[gnu::always_inline]] inline void store(double* p, const V& v) {
  std::memcpy(p, &v, sizeof v);
}

template <class V>
using Vec = std::array<V, 3>;

// Σ_{j=0..k} a^[j] × b^[k−j] (orbit_taylor.cpp's cross_sum).
template <class V>
[[gnu::always_inline]] inline Vec<V> cross_sum(const Vec<V>* a, const Vec<V>* b, int k) {
  Vec<V> s{V{}, V{}, V{}};
  for (int j = 0; j <= k; ++j) {
    const Vec<V>& p = a[j];
    const Vec<V>& q = b[k - j];
    s[0] = s[0] + (p[1] * q[2] - p[2] * q[1]);
    s[1] = s[1] + (p[2] * q[0] - p[0] * q[2]);
    s[2] = s[2] + (p[0] * q[1] - p[1] * q[0]);
  }
  return s;
}

// Σ_{j=0..k} f^[j] v^[k−j] (orbit_taylor.cpp's scale_sum).
template <class V>
[[gnu::always_inline]] inline Vec<V> scale_sum(const V* f, const Vec<V>* v, int k) {
  Vec<V> s{V{}, V{}, V{}};
  for (int j = 0; j <= k; ++j) {
    for (int c = 0; c < 3; ++c) s[c] = s[c] + f[j] * v[k - j][c];
  }
  return s;
}

// The series of (m, γ, n), ω = I⁻¹(m − k) and Iγ, order by order (orbit_taylor.cpp's OrbitSeries).
template <class V, int L>
struct Series {
  Vec<V> m[K], g[K], nrm[K], w[K], ig[K];
  Vec<V> inertia, gyrostat;

  bool tangent = false;  // a tangent vector's series: δω = I⁻¹ δm, no gyrostatic moment

  // The coefficient 0 from x (a state, or with `tangent_` a tangent vector), written to out.
  Series(const double* consts, const double* x, double* out, bool tangent_ = false)
      : tangent(tangent_) {
    load_constants(consts);
    set(0, vec(x, 0), vec(x, 3), vec(x, 6), out);
  }
  // The state's series 0..order from the coefficients the state kernel wrote.
  Series(const double* consts, const double* series, int order) {
    load_constants(consts);
    for (int k = 0; k <= order; ++k) {
      const double* at = series + 9 * k * L;
      set(k, vec(at, 0), vec(at, 3), vec(at, 6), nullptr);
    }
  }
  void set(int k, const Vec<V>& mk, const Vec<V>& gk, const Vec<V>& nk, double* out) {
    m[k] = mk;
    g[k] = gk;
    nrm[k] = nk;
    for (int c = 0; c < 3; ++c) {
      w[k][c] = (k == 0 && !tangent ? mk[c] - gyrostat[c] : mk[c]) / inertia[c];
      ig[k][c] = inertia[c] * gk[c];
      if (out == nullptr) continue;
      store(out + (9 * k + c) * L, mk[c]);
      store(out + (9 * k + 3 + c) * L, gk[c]);
      store(out + (9 * k + 6 + c) * L, nk[c]);
    }
  }

 private:
  void load_constants(const double* consts) {
    for (int c = 0; c < 3; ++c) {
      inertia[c] = load<V>(consts + (kOrbitInertia + c) * L);
      gyrostat[c] = load<V>(consts + (kOrbitGyrostat + c) * L);
    }
  }
  static Vec<V> vec(const double* x, int at) {
    return {load<V>(x + at * L), load<V>(x + (at + 1) * L), load<V>(x + (at + 2) * L)};
  }
};

// Σ_{j=0..k} δa^[j] × b^[k−j] + a^[j] × δb^[k−j] (orbit_taylor_tangent.cpp's tangent_cross).
template <class V>
[[gnu::always_inline]] inline Vec<V> tangent_cross(const Vec<V>* da, const Vec<V>* b,
                                                   const Vec<V>* a, const Vec<V>* db, int k) {
  Vec<V> s{V{}, V{}, V{}};
  for (int j = 0; j <= k; ++j) {
    const Vec<V>&p = da[j], &q = b[k - j], &r = a[j], &u = db[k - j];
    s[0] = s[0] + ((p[1] * q[2] - p[2] * q[1]) + (r[1] * u[2] - r[2] * u[1]));
    s[1] = s[1] + ((p[2] * q[0] - p[0] * q[2]) + (r[2] * u[0] - r[0] * u[2]));
    s[2] = s[2] + ((p[0] * q[1] - p[1] * q[0]) + (r[0] * u[1] - r[1] * u[0]));
  }
  return s;
}

// The series 0..order − 1 of σ and σλ of each lane (orbit_taylor.cpp's orbit_anomaly_series).
template <class V, int L>
void anomaly_series(const double* consts, int order, V* sigma, V* sigma_lambda) {
  const V e = load<V>(consts + kOrbitEccentricity * L);
  const V c_sigma = load<V>(consts + kOrbitSigma * L);
  const V c_lambda = load<V>(consts + kOrbitSigmaLambda * L);
  const V cos0 = load<V>(consts + kOrbitCos * L), sin0 = load<V>(consts + kOrbitSin * L);
  V u[K], inv_u[K];
  double factorial_inv = 1.0;
  for (int k = 0; k < order; ++k) {
    if (k > 0) factorial_inv /= static_cast<double>(k);
    const V derivative = k % 4 == 0 ? cos0 : k % 4 == 1 ? -sin0 : k % 4 == 2 ? -cos0 : sin0;
    u[k] = (k == 0 ? 1.0 : 0.0) + e * derivative * factorial_inv;
    V r = V{} + (k == 0 ? 1.0 : 0.0);
    for (int j = 1; j <= k; ++j) r = r - u[j] * inv_u[k - j];
    inv_u[k] = r / u[0];
    V sq{};
    for (int j = 0; j <= k; ++j) sq = sq + inv_u[j] * inv_u[k - j];
    sigma[k] = c_sigma * sq;
    sigma_lambda[k] = c_lambda * u[k];
  }
}

// orbit_taylor_expand on a circular orbit: x^[k+1] = (m × ω + λ γ × Iγ, γ × ω + ω0 n × γ,
// n × ω)^[k] / (k + 1).
template <class V, int L>
void expand_circular(const double* consts, const double* x, int order, double* series) {
  Series<V, L> z(consts, x, series);
  const V rate = load<V>(consts + kOrbitRate * L), lambda = load<V>(consts + kOrbitLambda * L);
  for (int k = 0; k < order; ++k) {
    const double inv = 1.0 / static_cast<double>(k + 1);
    const Vec<V> mw = cross_sum(z.m, z.w, k), gig = cross_sum(z.g, z.ig, k),
                 gw = cross_sum(z.g, z.w, k), ng = cross_sum(z.nrm, z.g, k),
                 nw = cross_sum(z.nrm, z.w, k);
    Vec<V> dm, dg, dn;
    for (int c = 0; c < 3; ++c) {
      dm[c] = (mw[c] + lambda * gig[c]) * inv;
      dg[c] = (gw[c] + rate * ng[c]) * inv;
      dn[c] = nw[c] * inv;
    }
    z.set(k + 1, dm, dg, dn, series);
  }
}

// orbit_taylor_expand on an ellipse, in ν: the series of u = 1 + e cos ν, 1/u, σ ∝ 1/u² and
// σλ ∝ u from the derivatives of cos ν, then the products multiplied by them.
template <class V, int L>
void expand_elliptic(const double* consts, const double* x, int order, double* series) {
  V sigma[K], sigma_lambda[K];
  anomaly_series<V, L>(consts, order, sigma, sigma_lambda);
  Series<V, L> z(consts, x, series);
  Vec<V> mw[K], gig[K], gw[K], nw[K];  // the series of m × ω, γ × Iγ, γ × ω, n × ω
  for (int k = 0; k < order; ++k) {
    mw[k] = cross_sum(z.m, z.w, k);
    gig[k] = cross_sum(z.g, z.ig, k);
    gw[k] = cross_sum(z.g, z.w, k);
    nw[k] = cross_sum(z.nrm, z.w, k);
    const double inv = 1.0 / static_cast<double>(k + 1);
    const Vec<V> sm = scale_sum(sigma, mw, k), sl = scale_sum(sigma_lambda, gig, k),
                 sg = scale_sum(sigma, gw, k), ng = cross_sum(z.nrm, z.g, k),
                 sn = scale_sum(sigma, nw, k);
    Vec<V> dm, dg, dn;
    for (int c = 0; c < 3; ++c) {
      dm[c] = (sm[c] + sl[c]) * inv;
      dg[c] = (sg[c] + ng[c]) * inv;
      dn[c] = sn[c] * inv;
    }
    z.set(k + 1, dm, dg, dn, series);
  }
}

// orbit_taylor_expand_tangent on a circular orbit: δṁ = δm × ω + m × δω + λ (δγ × Iγ + γ × Iδγ),
// δγ̇ = δγ × ω + γ × δω + ω0 (δn × γ + n × δγ), δṅ = δn × ω + n × δω.
template <class V, int L>
void expand_tangent_circular(const double* consts, const double* series, const double* v, int order,
                             double* tangent) {
  const Series<V, L> x(consts, series, order);
  Series<V, L> d(consts, v, tangent, true);
  const V rate = load<V>(consts + kOrbitRate * L), lambda = load<V>(consts + kOrbitLambda * L);
  for (int k = 0; k < order; ++k) {
    const double inv = 1.0 / static_cast<double>(k + 1);
    const Vec<V> mw = tangent_cross(d.m, x.w, x.m, d.w, k),
                 gig = tangent_cross(d.g, x.ig, x.g, d.ig, k),
                 gw = tangent_cross(d.g, x.w, x.g, d.w, k),
                 ng = tangent_cross(d.nrm, x.g, x.nrm, d.g, k),
                 nw = tangent_cross(d.nrm, x.w, x.nrm, d.w, k);
    Vec<V> dm, dg, dn;
    for (int c = 0; c < 3; ++c) {
      dm[c] = (mw[c] + lambda * gig[c]) * inv;
      dg[c] = (gw[c] + rate * ng[c]) * inv;
      dn[c] = nw[c] * inv;
    }
    d.set(k + 1, dm, dg, dn, tangent);
  }
}

// orbit_taylor_expand_tangent on an ellipse, in ν: the products multiplied by σ and σλ.
template <class V, int L>
void expand_tangent_elliptic(const double* consts, const double* series, const double* v, int order,
                             double* tangent) {
  V sigma[K], sigma_lambda[K];
  anomaly_series<V, L>(consts, order, sigma, sigma_lambda);
  const Series<V, L> x(consts, series, order);
  Series<V, L> d(consts, v, tangent, true);
  Vec<V> mw[K], gig[K], gw[K], nw[K];
  for (int k = 0; k < order; ++k) {
    mw[k] = tangent_cross(d.m, x.w, x.m, d.w, k);
    gig[k] = tangent_cross(d.g, x.ig, x.g, d.ig, k);
    gw[k] = tangent_cross(d.g, x.w, x.g, d.w, k);
    nw[k] = tangent_cross(d.nrm, x.w, x.nrm, d.w, k);
    const double inv = 1.0 / static_cast<double>(k + 1);
    const Vec<V> sm = scale_sum(sigma, mw, k), sl = scale_sum(sigma_lambda, gig, k),
                 sg = scale_sum(sigma, gw, k), ng = tangent_cross(d.nrm, x.g, x.nrm, d.g, k),
                 sn = scale_sum(sigma, nw, k);
    Vec<V> dm, dg, dn;
    for (int c = 0; c < 3; ++c) {
      dm[c] = (sm[c] + sl[c]) * inv;
      dg[c] = (sg[c] + ng[c]) * inv;
      dn[c] = sn[c] * inv;
    }
    d.set(k + 1, dm, dg, dn, tangent);
  }
}

}  // namespace orbit_taylor_simd
}  // namespace newtop::detail
