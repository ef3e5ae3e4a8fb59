#pragma once
// The kernels of the Taylor ensemble (taylor_ensemble.hpp; private to src/integrate): Taylor's
// recurrences and the sum of the series, one trajectory per lane of a vector of L doubles, in
// structure-of-arrays form. Each lane does the operations of taylor_recurrences.hpp's expand_lanes
// and of taylor_lanes::sum_series for one component after another, in their order: where those hold
// the components (x, y, z) in lanes and rotate them, (y, z, x) and (z, x, y), these kernels hold
// component c + 1 and c + 2 (mod 3) in registers of their own. Compiled with -ffp-contract=off
// (CMakeLists.txt), so that no a·b + c is fused but those the recurrences fuse explicitly (F::fma):
// the same bits as the scalar recurrences.
//
// Layouts, for L lanes: the constants (kConstants rows: 1/I, k, b, d_spin, d_field, three
// components each) at consts[(3 q + c) L + l]; a state (m, γ) at x[c L + l], c = 0..5; the
// coefficient n of the series at series[(6 n + c) L + l].

#include <array>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "taylor_math.hpp"

namespace newtop::detail {

inline constexpr int kTaylorLaneConstants = 15;  // inv_i, k, b, d_spin, d_field
inline constexpr int kTaylorLaneWidth = 8;       // the widest lane count (AVX-512)

/// One kernel's entry points, for an instruction set.
struct TaylorLaneKernel {
  int lanes;
  void (*expand)(const double* consts, const double* x, int order, double* series);
  void (*sum)(const double* series, int order, const double* h, double* out);
  /// The series summed at h[l] (as `sum`) in each lane l whose bit is set in `lanes`, written over
  /// the state x where all six components are finite; returns the bits of the lanes written.
  unsigned (*advance)(const double* series, int order, const double* h, unsigned lanes, double* x);
  void (*expand_tangent)(const double* consts, const double* series, const double* v, int order,
                         double* tangent);
  /// The max norms (taylor_lanes::pair_norm) of the coefficients 0, order − 1 and order of each
  /// lane's series, at norms[k L + l]; with `tangent`, nan_max of the state's and the tangent's.
  void (*norms)(const double* series, const double* tangent, int order, double* norms);
  /// taylor_math::regular_step of each lane from its norms (as `norms` writes them), at steps[l]:
  /// the lane's step where its norms p − 1 and p are finite and nonzero.
  void (*steps)(const double* norms, int order, double abs_tol, double rel_tol, double* steps);
};

TaylorLaneKernel taylor_lane_kernel_portable();
#if defined(__x86_64__) && defined(__GNUC__)
TaylorLaneKernel taylor_lane_kernel_avx2();
TaylorLaneKernel taylor_lane_kernel_avx512();
#endif

namespace taylor_ensemble_simd {

// The coefficients of a series, 0..kMaxOrder (TaylorSeries::kMaxOrder; taylor_ensemble.cpp checks
// it), and 1/(n + 1) as taylor_lanes::kInverse holds it: this header stays free of Eigen, whose
// headers refuse -mavx512f without -mfma.
inline constexpr int K = 41;
inline constexpr std::array<double, K> kInverse = [] {
  std::array<double, K> a{};
  for (int n = 0; n < K; ++n) a[static_cast<std::size_t>(n)] = 1.0 / static_cast<double>(n + 1);
  return a;
}();

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

// The sums of one order and one component c (expand_lanes: P, Rs, S, T of c).
template <class V>
struct Sums {
  V p{}, rs{}, s{}, t{};
};

// expand_lanes's pair(a, c) for the component c (its neighbours c1 = c + 1, c2 = c + 2 mod 3): the
// terms j and n − j of the Cauchy sums, each product added by a fused multiply-add (F::fma).
template <class F, class V>
[[gnu::always_inline]] inline void pair(const V (&wa)[3], const V (&ga)[3], const V (&wc)[3],
                                        const V (&gc)[3], int c1, int c2, Sums<V>& z) {
  z.p = F::fma(wc[c1], wa[c2], F::fma(wa[c1], wc[c2], z.p));
  z.rs = F::fma(gc[c1], ga[c2], F::fma(ga[c1], gc[c2], z.rs));
  z.s = F::fma(gc[c1], wa[c2], F::fma(ga[c1], wc[c2], z.s));
  z.t = F::fma(gc[c2], wa[c1], F::fma(ga[c2], wc[c1], z.t));
}

// expand_lanes's single(a) for the component c: the term j = n − j.
template <class F, class V>
[[gnu::always_inline]] inline void single(const V (&w)[3], const V (&g)[3], int c1, int c2,
                                          Sums<V>& z) {
  z.p = F::fma(w[c1], w[c2], z.p);
  z.rs = F::fma(g[c1], g[c2], z.rs);
  z.s = F::fma(g[c1], w[c2], z.s);
  z.t = F::fma(g[c2], w[c1], z.t);
}

// The model's numbers of each lane (consts, the layout above).
template <class V, int L>
struct LaneConstants {
  V inv_i[3], k[3], b[3], d_spin[3], d_field[3];
  explicit LaneConstants(const double* consts) {
    for (int c = 0; c < 3; ++c) {
      inv_i[c] = load<V>(consts + (0 + c) * L);
      k[c] = load<V>(consts + (3 + c) * L);
      b[c] = load<V>(consts + (6 + c) * L);
      d_spin[c] = load<V>(consts + (9 + c) * L);
      d_field[c] = load<V>(consts + (12 + c) * L);
    }
  }
};

// The coefficient 0 of the series through x, written to series; ω^[0] and γ^[0] into w0, g0.
template <class V, int L>
[[gnu::always_inline]] inline void start_series(const LaneConstants<V, L>& q, const double* x,
                                                double* series, V (&w0)[3], V (&g0)[3]) {
  for (int c = 0; c < 3; ++c) {
    const V m = load<V>(x + c * L);
    g0[c] = load<V>(x + (3 + c) * L);
    store(series + c * L, m);
    store(series + (3 + c) * L, g0[c]);
    w0[c] = (m - q.k[c]) * q.inv_i[c];
  }
}

// The coefficient n + 1 of the component c from its sums z of order n (expand_lanes's last lines):
// m^[n+1] and γ^[n+1] written to next, ω^[n+1] and γ^[n+1] into w1, g1.
template <class V, int L>
[[gnu::always_inline]] inline void finish_component(const LaneConstants<V, L>& q, int c,
                                                    const V (&w)[3], const V (&g)[3],
                                                    const Sums<V>& z, double inv, double* next,
                                                    V (&w1)[3], V (&g1)[3]) {
  const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
  const V linear = (q.k[c1] * w[c2] - q.k[c2] * w[c1]) + (g[c1] * q.b[c2] - g[c2] * q.b[c1]);
  const V m_next = (q.d_spin[c] * z.p + q.d_field[c] * z.rs + linear) * inv;
  store(next + c * L, m_next);
  w1[c] = m_next * q.inv_i[c];
  g1[c] = (z.s - z.t) * inv;
  store(next + (3 + c) * L, g1[c]);
}

// The coefficients 0..order of the series through x (expand_lanes without attitude).
// One component after another (eight sums in registers, not 24), each sum over j in expand_lanes's
// order: the same bits. F::fma(a, b, c): a·b + c rounded once, lane by lane.
template <class V, int L, class F>
void expand(const double* consts, const double* x, int order, double* series) {
  const LaneConstants<V, L> q(consts);
  V w[K][3], g[K][3];  // ω^[n], γ^[n]
  start_series(q, x, series, w[0], g[0]);
  for (int n = 0; n < order; ++n) {
    const int last_pair = (n - 1) / 2;
    const double inv = kInverse[static_cast<std::size_t>(n)];
    double* next = series + 6 * (n + 1) * L;
    auto component = [&](auto c_) {  // c a constant: its neighbours' indices fixed
      constexpr int c = decltype(c_)::value, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      Sums<V> a, bsum;  // the two interleaved halves (P and Pb in expand_lanes)
      int j = 1;
      for (; j + 1 <= last_pair; j += 2) {
        pair<F>(w[j], g[j], w[n - j], g[n - j], c1, c2, a);
        pair<F>(w[j + 1], g[j + 1], w[n - j - 1], g[n - j - 1], c1, c2, bsum);
      }
      if (j == last_pair) pair<F>(w[j], g[j], w[n - j], g[n - j], c1, c2, a);
      if (n % 2 == 0 && n > 0) single<F>(w[n / 2], g[n / 2], c1, c2, bsum);
      a.p += bsum.p;
      a.rs += bsum.rs;
      a.s += bsum.s;
      a.t += bsum.t;
      if (n == 0) {
        single<F>(w[0], g[0], c1, c2, a);
      } else {
        pair<F>(w[0], g[0], w[n], g[n], c1, c2, a);
      }
      finish_component(q, c, w[n], g[n], a, inv, next, w[n + 1], g[n + 1]);
    };
    component(std::integral_constant<int, 0>{});
    component(std::integral_constant<int, 1>{});
    component(std::integral_constant<int, 2>{});
  }
}

// The coefficients 0..order of one tangent vector v along the state's series
// (phase/taylor_tangent_lanes.hpp, expand_tangent_lanes with one column): the state's ω^[n] formed
// again from its m^[n] as there. Each sum is Σ_{j=0..n} (δa^[j] b^[n−j] + a^[n−j] δb^[j]), one
// chain of fused multiply-adds, j from 0 to n, as there: the same bits. With 32 registers (AVX-512)
// the three components at once: the twelve coefficients δ^[j] and x^[n−j] loaded once for the 24
// products of the twelve sums (each coefficient used in four); with fewer, one component after
// another (its four sums and eight coefficients in registers).
template <class V, int L, class F>
void expand_tangent(const double* consts, const double* series, const double* v, int order,
                    double* tangent) {
  const LaneConstants<V, L> q(consts);
  V xw[K][3], xg[K][3], dw[K][3], dg[K][3];  // the state's ω^[n], γ^[n]; the tangent's
  for (int n = 0; n < order; ++n) {
    for (int c = 0; c < 3; ++c) {
      const V m = load<V>(series + (6 * n + c) * L);
      xw[n][c] = (n == 0 ? m - q.k[c] : m) * q.inv_i[c];
      xg[n][c] = load<V>(series + (6 * n + 3 + c) * L);
    }
  }
  for (int c = 0; c < 3; ++c) {
    const V m = load<V>(v + c * L);
    dw[0][c] = m * q.inv_i[c];
    dg[0][c] = load<V>(v + (3 + c) * L);
    store(tangent + c * L, m);
    store(tangent + (3 + c) * L, dg[0][c]);
  }
  // The term j of the component c's four sums (its neighbours c1, c2): the tangent's δ^[j] (dw_j,
  // dg_j) with the state's x^[n−j] (xw_n, xg_n).
  auto term = [](const V(&dw_j)[3], const V(&dg_j)[3], const V(&xw_n)[3], const V(&xg_n)[3], int c1,
                 int c2, Sums<V>& z) {
    z.p = F::fma(xw_n[c1], dw_j[c2], F::fma(dw_j[c1], xw_n[c2], z.p));
    z.rs = F::fma(xg_n[c1], dg_j[c2], F::fma(dg_j[c1], xg_n[c2], z.rs));
    z.s = F::fma(xg_n[c1], dw_j[c2], F::fma(dg_j[c1], xw_n[c2], z.s));
    z.t = F::fma(xg_n[c2], dw_j[c1], F::fma(dg_j[c2], xw_n[c1], z.t));
  };
  for (int n = 0; n < order; ++n) {
    const double inv = kInverse[static_cast<std::size_t>(n)];
    double* next = tangent + 6 * (n + 1) * L;
    Sums<V> z[3];
    if constexpr (sizeof(V) == 64) {
      for (int j = 0; j <= n; ++j) {
        term(dw[j], dg[j], xw[n - j], xg[n - j], 1, 2, z[0]);
        term(dw[j], dg[j], xw[n - j], xg[n - j], 2, 0, z[1]);
        term(dw[j], dg[j], xw[n - j], xg[n - j], 0, 1, z[2]);
      }
    } else {
      for (int j = 0; j <= n; ++j) term(dw[j], dg[j], xw[n - j], xg[n - j], 1, 2, z[0]);
      for (int j = 0; j <= n; ++j) term(dw[j], dg[j], xw[n - j], xg[n - j], 2, 0, z[1]);
      for (int j = 0; j <= n; ++j) term(dw[j], dg[j], xw[n - j], xg[n - j], 0, 1, z[2]);
    }
    for (int c = 0; c < 3; ++c) {
      const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      const V dm = (q.d_spin[c] * z[c].p + q.d_field[c] * z[c].rs +
                    (q.k[c1] * dw[n][c2] - q.k[c2] * dw[n][c1]) +
                    (dg[n][c1] * q.b[c2] - dg[n][c2] * q.b[c1])) *
                   inv;
      store(next + c * L, dm);
      dw[n + 1][c] = dm * q.inv_i[c];
      dg[n + 1][c] = (z[c].s - z[c].t) * inv;
      store(next + (3 + c) * L, dg[n + 1][c]);
    }
  }
}

// |v| lane by lane (std::abs: the sign bit cleared).
template <class V, int L>
[[gnu::always_inline]] inline V abs_of(V v) {
  for (int i = 0; i < L; ++i) v[i] = __builtin_fabs(v[i]);
  return v;
}

// taylor_lanes::nan_max, lane by lane: a where a >= b or a is NaN, b elsewhere.
template <class V>
[[gnu::always_inline]] inline V nan_max(V a, V b) {
  return ((a >= b) | (a != a)) ? a : b;
}

// taylor_lanes::pair_norm of the coefficient n, lane by lane: the same selections (norm_inf keeps
// a component unless it is <= the norm so far).
template <class V, int L>
[[gnu::always_inline]] inline V pair_norm(const double* series, int n) {
  V half[2] = {V{}, V{}};
  for (int h = 0; h < 2; ++h) {
    for (int c = 0; c < 3; ++c) {
      const V v = abs_of<V, L>(load<V>(series + (6 * n + 3 * h + c) * L));
      half[h] = (v <= half[h]) ? half[h] : v;
    }
  }
  return nan_max(half[0], half[1]);
}

template <class V, int L>
void norms(const double* series, const double* tangent, int order, double* out) {
  const int at[3] = {0, order - 1, order};
  for (int k = 0; k < 3; ++k) {
    V r = pair_norm<V, L>(series, at[k]);
    if (tangent != nullptr) r = nan_max(r, pair_norm<V, L>(tangent, at[k]));
    store(out + k * L, r);
  }
}

template <class V, int L>
void steps(const double* norms, int order, double abs_tol, double rel_tol, double* out) {
  store(out, taylor_math::regular_step(load<V>(norms), load<V>(norms + L), load<V>(norms + 2 * L),
                                       abs_tol, rel_tol, order));
}

// The series summed at h, a step per lane (taylor_lanes::sum_series: Horner in h² over the even
// and the odd coefficients).
template <class V, int L>
[[gnu::always_inline]] inline void sum_lanes(const double* series, int order, const V& h,
                                             V (&out)[6]) {
  const V h2 = h * h;
  auto horner = [&](int top, V(&x)[6]) {
    for (int c = 0; c < 6; ++c) x[c] = load<V>(series + (6 * top + c) * L);
    for (int n = top - 2; n >= 0; n -= 2) {
      for (int c = 0; c < 6; ++c) x[c] = x[c] * h2 + load<V>(series + (6 * n + c) * L);
    }
  };
  const int odd = order % 2;  // the highest order is odd
  V even[6], other[6];
  horner(order - odd, even);
  horner(order - 1 + odd, other);
  for (int c = 0; c < 6; ++c) out[c] = even[c] + other[c] * h;
}

template <class V, int L>
void sum(const double* series, int order, const double* h_lanes, double* out) {
  V x[6];
  sum_lanes<V, L>(series, order, load<V>(h_lanes), x);
  for (int c = 0; c < 6; ++c) store(out + c * L, x[c]);
}

template <class V, int L>
unsigned advance(const double* series, int order, const double* h_lanes, unsigned lanes,
                 double* x) {
  using M = decltype(V{} == V{});  // a lane mask
  V trial[6];
  sum_lanes<V, L>(series, order, load<V>(h_lanes), trial);
  M index{};
  for (int l = 0; l < L; ++l) index[l] = l;
  M write = ((M{} + static_cast<long>(lanes)) >> index & 1) != 0;
  for (int c = 0; c < 6; ++c) write &= (trial[c] - trial[c]) == 0.0;  // finite (is_finite)
  for (int c = 0; c < 6; ++c) store(x + c * L, write ? trial[c] : load<V>(x + c * L));
  unsigned written = 0;
  for (int l = 0; l < L; ++l) written |= write[l] != 0 ? 1u << l : 0u;
  return written;
}

}  // namespace taylor_ensemble_simd
}  // namespace newtop::detail
