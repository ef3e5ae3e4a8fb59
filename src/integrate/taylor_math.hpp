#pragma once
// The logarithm and the power of two of Taylor's step rule (taylor_lanes.hpp, step_from_norms;
// private to the library; docs/methods.md, "Taylor"), and the step itself: a fixed sequence of
// IEEE operations (+, −, ×, ÷, comparisons, selections and exact integer work on the bits), written
// once for a double and for GCC's vectors of doubles, so that a lane of a vector gives the bits of
// the scalar call whatever the instruction set. The files that include it are compiled with
// -ffp-contract=off (CMakeLists.txt): no a·b + c is fused.
//
// step_log2(x): x = 2^e m with m in [√½, √2), s = (m − 1)/(m + 1), log2 m = (2/ln 2) atanh s =
// (2/ln 2)(s + s³/3 + … + s²¹/21) (Estrin's scheme in s²) (|s| ≤ 0.1716: the first term left out is
// below 1e-18 of the sum). Error: at most kTaylorStepLog2Ulps (taylor.hpp) units in the last place
// of the result for finite x > 0 (tests/integrate/test_taylor_math.cpp measures it against the C
// library); log2 0 = −inf, log2 +inf = +inf, NaN for x < 0 or NaN.
//
// step_exp2(y): y = k + r, k the nearest integer, |r| ≤ ½, 2^r = 1 + r Σ_{1 ≤ i ≤ 13} (ln 2)^i
// r^(i−1) / i! (Estrin's scheme; the first term left out is below 5e-18), times 2^k as two exact
// powers of two (one rounding where the result is subnormal). Error: at most kTaylorStepExp2Ulps
// units in the last place for a normal result; y ≥ 1024 gives +inf, y below −1075 gives 0, NaN
// stays NaN.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace newtop::detail::taylor_math {

/// Jorba and Zou's safety factor exp(−0.7/(p − 1)) is 2^(−kSafetyLog2/(p − 1)): 0.7/ln 2.
inline constexpr double kSafetyLog2 = 0x1.0287ec6d1a87fp+0;

// A double of D (double, or a vector of them) with every lane c.
template <class D>
[[gnu::always_inline]] inline D splat(double c) {
  return D{} + c;
}

// The unsigned 64-bit integers of D's lanes.
template <std::size_t Bytes>
struct BitsOfSize;
template <>
struct BitsOfSize<8> {
  using type = std::uint64_t;
};
template <>
struct BitsOfSize<16> {
  typedef std::uint64_t type __attribute__((vector_size(16)));
};
template <>
struct BitsOfSize<32> {
  typedef std::uint64_t type __attribute__((vector_size(32)));
};
template <>
struct BitsOfSize<64> {
  typedef std::uint64_t type __attribute__((vector_size(64)));
};
template <class D>
using BitsOf = BitsOfSize<sizeof(D)>;

// Σ_i a_i x^i by Estrin's scheme (pairs a_2i + a_2i+1 x, then pairs of those with x², x⁴, …): the
// short chain of operations keeps the scalar step's latency low.
template <class D, std::size_t N>
[[gnu::always_inline]] inline D estrin(const std::array<D, N>& a, D x) {
  if constexpr (N == 1) {
    return a[0];
  } else {
    std::array<D, (N + 1) / 2> b;
    for (std::size_t k = 0; 2 * k < N; ++k) {
      b[k] = 2 * k + 1 < N ? a[2 * k] + a[2 * k + 1] * x : a[2 * k];
    }
    return estrin(b, x * x);
  }
}

template <class D, std::size_t N>
[[gnu::always_inline]] inline D estrin(const double (&c)[N], D x) {
  std::array<D, N> a;
  for (std::size_t i = 0; i < N; ++i) a[i] = splat<D>(c[i]);
  return estrin(a, x);
}

template <class D>
[[gnu::always_inline]] inline D step_log2(D x) {
  using U = typename BitsOf<D>::type;
  constexpr double c[11] = {0x1.71547652b82fep+1, 0x1.ec709dc3a03fdp-1, 0x1.2776c50ef9bfep-1,
                            0x1.a61762a7aded9p-2, 0x1.484b13d7c02a9p-2, 0x1.0c9a84994022dp-2,
                            0x1.c68f568d31760p-3, 0x1.89f3b1694cffep-3, 0x1.5b9ac9b743f0dp-3,
                            0x1.3703c1f4d0ffep-3, 0x1.1964ec6fc9491p-3};  // 2/((2i + 1) ln 2)
  const auto tiny = x < 0x1p-1022;  // subnormal: scaled by 2^54 first
  const D xs = tiny ? x * 0x1p54 : x;
  const U b = std::bit_cast<U>(xs);
  const D m1 = std::bit_cast<D>((b & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);  // [1, 2)
  // The biased exponent as a double: 2^52 + e_b − 2^52 − 1023, exact.
  const D e1 = std::bit_cast<D>((b >> 52) | 0x4330000000000000ULL) - (0x1p52 + 1023.0);
  const auto big = m1 > 0x1.6a09e667f3bcdp+0;  // √2
  const D m = big ? m1 * 0.5 : m1;
  const D e = (big ? e1 + 1.0 : e1) - (tiny ? splat<D>(54.0) : splat<D>(0.0));
  const D s = (m - 1.0) / (m + 1.0);
  const D r = e + s * estrin(c, s * s);
  constexpr double inf = std::numeric_limits<double>::infinity();
  const D special =
      x == 0.0 ? splat<D>(-inf)
               : (x < 0.0 ? splat<D>(std::numeric_limits<double>::quiet_NaN()) : x);  // +inf, NaN
  return ((x > 0.0) & (x < inf)) ? r : special;
}

template <class D>
[[gnu::always_inline]] inline D step_exp2(D y) {
  using U = typename BitsOf<D>::type;
  constexpr double c[13] = {0x1.62e42fefa39efp-1,  0x1.ebfbdff82c58fp-3,  0x1.c6b08d704a0c0p-5,
                            0x1.3b2ab6fba4e77p-7,  0x1.5d87fe78a6731p-10, 0x1.430912f86c787p-13,
                            0x1.ffcbfc588b0c7p-17, 0x1.62c0223a5c824p-20, 0x1.b5253d395e7c4p-24,
                            0x1.e4cf5158b8ecap-28, 0x1.e8cac7351bb25p-32, 0x1.c3bd650fc2986p-36,
                            0x1.816193166d0f9p-40};  // (ln 2)^i / i!, i = 1..13
  constexpr double shift = 0x1.8p52;                 // adding it rounds |y| < 2^51 to an integer
  D yc = y > 1100.0 ? splat<D>(1100.0) : y;          // NaN stays NaN
  yc = yc < -1100.0 ? splat<D>(-1100.0) : yc;
  const D t = yc + shift;
  const D r = yc - (t - shift);  // exact, |r| <= 1/2
  // k + 1100 in [0, 2200] from the low bits of t, split k = k1 + k2 with k1, k2 in [−550, 550].
  const U u = std::bit_cast<U>(t) - (std::bit_cast<std::uint64_t>(shift) - 1100);
  const U u1 = u >> 1, u2 = u - u1;
  const D s1 = std::bit_cast<D>((u1 + (1023 - 550)) << 52);
  const D s2 = std::bit_cast<D>((u2 + (1023 - 550)) << 52);
  return ((1.0 + r * estrin(c, r)) * s1) * s2;
}

/// The step of a series of order p whose coefficients p − 1 and p have the finite nonzero max
/// norms c_q and c_p, coefficient 0 the norm c_0: min over n = p − 1, p of (ε/c_n)^(1/n) with
/// ε = max(abs_tol, rel_tol c_0), times 2^(−kSafetyLog2/(p − 1)) (step_from_norms in that case).
template <class D>
[[gnu::always_inline]] inline D regular_step(D c_0, D c_q, D c_p, double abs_tol, double rel_tol,
                                             int p) {
  const D scaled = rel_tol * c_0;
  const D log_eps = step_log2(abs_tol < scaled ? scaled : splat<D>(abs_tol));  // std::max
  const D a = (log_eps - step_log2(c_p)) / static_cast<double>(p);
  const D b = (log_eps - step_log2(c_q)) / static_cast<double>(p - 1);
  const D log_h = b < a ? b : a;  // std::min(a, b)
  return step_exp2(log_h - kSafetyLog2 / (p - 1));
}

}  // namespace newtop::detail::taylor_math
