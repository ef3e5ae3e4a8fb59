#pragma once
// The lanes of Taylor's recurrences (taylor.cpp, phase/taylor_tangent.cpp; private to the library):
// 4-lane AVX2 vectors or pairs of 2-lane ones, the same lane-wise operations on both, and the
// helpers the state's and the tangent's series share (the step from the coefficients' norms, the
// sum of a series).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__x86_64__) && defined(__GNUC__) && defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

#include "newtop/integrate/taylor.hpp"
#include "taylor_math.hpp"

namespace newtop::detail::taylor_lanes {

using Lanes = TaylorSeries::Lanes;
inline constexpr int K = TaylorSeries::kMaxOrder + 1;

// 1/(n + 1), n = 0..kMaxOrder − 1: the same doubles as the division, off the chain from one order
// to the next.
inline constexpr std::array<double, K> kInverse = [] {
  std::array<double, K> a{};
  for (int n = 0; n < K; ++n) a[static_cast<std::size_t>(n)] = 1.0 / static_cast<double>(n + 1);
  return a;
}();

// Four lanes in one AVX2 register (x86-64 with AVX2), or in two 2-lane registers (the baseline
// instruction set, where GCC would split a 4-lane vector through memory). The same operations on
// the same lanes in the same order either way.
using V4 = double __attribute__((vector_size(32)));
using V2 = double __attribute__((vector_size(16)));

struct Pair4 {
  V2 lo, hi;  // (x, y), (z, w)
};
[[gnu::always_inline]] inline Pair4 operator+(const Pair4& a, const Pair4& b) {
  return {a.lo + b.lo, a.hi + b.hi};
}
[[gnu::always_inline]] inline Pair4 operator-(const Pair4& a, const Pair4& b) {
  return {a.lo - b.lo, a.hi - b.hi};
}
[[gnu::always_inline]] inline Pair4 operator*(const Pair4& a, const Pair4& b) {
  return {a.lo * b.lo, a.hi * b.hi};
}
[[gnu::always_inline]] inline Pair4 operator*(const Pair4& a, double s) {
  return {a.lo * s, a.hi * s};
}
[[gnu::always_inline]] inline Pair4& operator+=(Pair4& a, const Pair4& b) { return a = a + b; }

template <class L>
struct LaneOps;

template <>
struct LaneOps<V4> {
  [[gnu::always_inline]] static V4 load(const Lanes& a) {
    V4 v;
    std::memcpy(&v, a.data(), sizeof v);
    return v;
  }
  [[gnu::always_inline]] static void store(Lanes& a, const V4& v) {
    std::memcpy(a.data(), &v, sizeof v);
  }
  [[gnu::always_inline]] static V4 rot1(const V4& a) {
    return __builtin_shufflevector(a, a, 1, 2, 0, 3);
  }  // (y, z, x, w)
  [[gnu::always_inline]] static V4 rot2(const V4& a) {
    return __builtin_shufflevector(a, a, 2, 0, 1, 3);
  }  // (z, x, y, w)
  [[gnu::always_inline]] static double lane(const V4& a, int i) { return a[i]; }
  [[gnu::always_inline]] static void set_w(V4& a, double w) { a[3] = w; }
  [[gnu::always_inline]] static V4 splat3(double w) { return V4{w, w, w, 0.0}; }
};

template <>
struct LaneOps<Pair4> {
  [[gnu::always_inline]] static Pair4 load(const Lanes& a) {
    return {V2{a[0], a[1]}, V2{a[2], a[3]}};
  }
  [[gnu::always_inline]] static void store(Lanes& a, const Pair4& v) {
    a = {v.lo[0], v.lo[1], v.hi[0], v.hi[1]};
  }
  [[gnu::always_inline]] static Pair4 rot1(const Pair4& a) {
    return {__builtin_shufflevector(a.lo, a.hi, 1, 2), __builtin_shufflevector(a.lo, a.hi, 0, 3)};
  }
  [[gnu::always_inline]] static Pair4 rot2(const Pair4& a) {
    return {__builtin_shufflevector(a.lo, a.hi, 2, 0), __builtin_shufflevector(a.lo, a.hi, 1, 3)};
  }
  [[gnu::always_inline]] static double lane(const Pair4& a, int i) {
    return i < 2 ? a.lo[i] : a.hi[i - 2];
  }
  [[gnu::always_inline]] static void set_w(Pair4& a, double w) { a.hi[1] = w; }
  [[gnu::always_inline]] static Pair4 splat3(double w) { return {V2{w, w}, V2{w, 0.0}}; }
};

// a·b + c rounded once, lane by lane (std::fma: the processor's instruction where it has one, the
// C library's exact emulation elsewhere; the same bits either way).
struct PairFma {
  static Pair4 fma(const Pair4& a, const Pair4& b, const Pair4& c) {
    return {V2{std::fma(a.lo[0], b.lo[0], c.lo[0]), std::fma(a.lo[1], b.lo[1], c.lo[1])},
            V2{std::fma(a.hi[0], b.hi[0], c.hi[0]), std::fma(a.hi[1], b.hi[1], c.hi[1])}};
  }
};

#if defined(__x86_64__) && defined(__GNUC__) && defined(__AVX2__) && defined(__FMA__)
// a·b + c rounded once, lane by lane, on V4: only in the files compiled for AVX2 and FMA
// (taylor_avx2.cpp, phase/taylor_tangent_avx2.cpp).
struct V4Fma {
  [[gnu::always_inline]] static V4 fma(const V4& a, const V4& b, const V4& c) {
    return _mm256_fmadd_pd(a, b, c);
  }
};
#endif

// The max norm of the first `lanes` lanes (NaN propagates).
inline double norm_inf(const Lanes& a, int lanes) {
  double n = 0.0;
  for (int i = 0; i < lanes; ++i) {
    const double v = std::abs(a[static_cast<std::size_t>(i)]);
    if (!(v <= n)) n = v;  // NaN propagates
  }
  return n;
}

inline double nan_max(double a, double b) { return a >= b || std::isnan(a) ? a : b; }

// The max norm of a coefficient (m^[n], γ^[n]) of the state or of a tangent vector.
inline double pair_norm(const Lanes& m, const Lanes& gamma) {
  return nan_max(norm_inf(m, 3), norm_inf(gamma, 3));
}

/// Whether a norm is finite and nonzero (the case of regular_step).
inline bool regular_norm(double c) {
  return c > 0.0 && c < std::numeric_limits<double>::infinity();
}

/// The step of a series of order p from the norms of its coefficients, norm(n) for n = 0..p:
/// min over n = p − 1, p of (ε / norm(n))^(1/n), ε = max(abs_tol, rel_tol norm(0)), times Jorba and
/// Zou's safety factor exp(−0.7/(p − 1)); if both vanish, the highest order that does not; none:
/// +inf (a constant solution); NaN for a series that is not finite. The powers as 2^(log2 …) with
/// the step rule's own step_log2 and step_exp2 (taylor_math.hpp); where the norms p − 1 and p are
/// finite and nonzero, regular_step's operations, which the ensemble's lanes repeat.
template <class Norm>
double step_from_norms(int p, Norm&& norm, double abs_tol, double rel_tol) {
  const double c_0 = norm(0), c_p = norm(p), c_q = norm(p - 1);
  if (regular_norm(c_p) && regular_norm(c_q)) {
    return taylor_math::regular_step(c_0, c_q, c_p, abs_tol, rel_tol, p);
  }
  const double log_eps = taylor_math::step_log2(std::max(abs_tol, rel_tol * c_0));
  double log_h = std::numeric_limits<double>::infinity();
  for (int n = p; n >= 1 && (n >= p - 1 || log_h == std::numeric_limits<double>::infinity()); --n) {
    const double c = n == p ? c_p : n == p - 1 ? c_q : norm(n);
    if (std::isnan(c) || std::isinf(c)) return std::numeric_limits<double>::quiet_NaN();
    if (c > 0.0) log_h = std::min(log_h, (log_eps - taylor_math::step_log2(c)) / n);
  }
  return taylor_math::step_exp2(log_h - taylor_math::kSafetyLog2 / (p - 1));
}

/// The series with coefficients (m^[n], γ^[n]), n = 0..order, summed at h.
State sum_series(const Lanes* m, const Lanes* gamma, int order, double h);

}  // namespace newtop::detail::taylor_lanes
