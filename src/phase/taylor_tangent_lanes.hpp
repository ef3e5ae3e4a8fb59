#pragma once
// Taylor's recurrences of the tangent vectors (taylor_tangent.cpp; private to the library), in
// lanes of either kind (integrate/taylor_lanes.hpp): instantiated with 2 × 2 lanes in
// taylor_tangent.cpp and with 4-lane AVX2 vectors in taylor_tangent_avx2.cpp, which is compiled for
// AVX2 and FMA (CMakeLists.txt) and run only where the processor has both.

#include "../integrate/taylor_lanes.hpp"
#include "newtop/phase/tangent_taylor.hpp"

namespace newtop::detail {

/// The coefficients 1..order of each column of ts along s in 4-lane AVX2 vectors
/// (taylor_tangent_avx2.cpp).
void taylor_expand_tangent_avx2(const TaylorModel& p, const TaylorSeries& s,
                                TaylorTangentSeries& ts);

namespace taylor_lanes {

// The coefficients 1..order of each column of ts from its coefficient 0, along s, in lanes L;
// F::fma(a, b, c) is a·b + c rounded once, lane by lane.
template <class L, class F>
[[gnu::always_inline]] inline void expand_tangent_lanes(const TaylorModel& p, const TaylorSeries& s,
                                                        TaylorTangentSeries& ts) {
  using O = LaneOps<L>;
  struct Rotated {
    L w1, w2, g1, g2;  // ω and γ (or δω and δγ) rotated once and twice
  };
  const int order = s.order;
  const L inv_i = O::load(p.inv_i), k = O::load(p.k), b = O::load(p.b), d_spin = O::load(p.d_spin),
          d_field = O::load(p.d_field);
  const L k1 = O::rot1(k), k2 = O::rot2(k), b1 = O::rot1(b), b2 = O::rot2(b);
  auto rotated = [](const L& w, const L& g) {
    return Rotated{O::rot1(w), O::rot2(w), O::rot1(g), O::rot2(g)};
  };
  Rotated X[K];  // the state's ω^[n], γ^[n]
  for (int n = 0; n < order; ++n) {
    const L m = O::load(s.m[static_cast<std::size_t>(n)]);
    X[n] = rotated((n == 0 ? m - k : m) * inv_i, O::load(s.gamma[static_cast<std::size_t>(n)]));
  }
  for (int c = 0; c < ts.columns; ++c) {
    auto& dm = ts.m[static_cast<std::size_t>(c)];
    auto& dg = ts.gamma[static_cast<std::size_t>(c)];
    Rotated D[K];  // δω^[n], δγ^[n]
    L dw = O::load(dm[0]) * inv_i, dgamma = O::load(dg[0]);
    for (int n = 0; n < order; ++n) {
      const Rotated& d = D[n] = rotated(dw, dgamma);
      // Σ_j δa^[j] b^[n−j] + a^[j] δb^[n−j] for ω₂ω₃ (P), γ₂γ₃ (Rs), γ₂ω₃ (S), γ₃ω₂ (T), cyclic in
      // the lanes, as Σ_{j=0..n} (δa^[j] b^[n−j] + a^[n−j] δb^[j]): the tangent's coefficient j
      // with the state's n − j, j from 0 (the oldest tangent coefficient) to n (the newest), each
      // sum one chain of fused multiply-adds, the two products of a term one after the other. The
      // kernels of the Taylor ensemble (integrate/taylor_ensemble_kernel.hpp) add the same
      // products in the same order: the same bits.
      L P{}, Rs{}, S{}, T{};
      for (int j = 0; j <= n; ++j) {
        const Rotated& dj = D[j];
        const Rotated& xn = X[n - j];
        P = F::fma(xn.w1, dj.w2, F::fma(dj.w1, xn.w2, P));
        Rs = F::fma(xn.g1, dj.g2, F::fma(dj.g1, xn.g2, Rs));
        S = F::fma(xn.g1, dj.w2, F::fma(dj.g1, xn.w2, S));
        T = F::fma(xn.g2, dj.w1, F::fma(dj.g2, xn.w1, T));
      }
      const double inv = kInverse[static_cast<std::size_t>(n)];
      const L dm_next =
          (d_spin * P + d_field * Rs + (k1 * d.w2 - k2 * d.w1) + (d.g1 * b2 - d.g2 * b1)) * inv;
      O::store(dm[static_cast<std::size_t>(n + 1)], dm_next);
      dw = dm_next * inv_i;
      dgamma = (S - T) * inv;
      O::store(dg[static_cast<std::size_t>(n + 1)], dgamma);
    }
  }
}

}  // namespace taylor_lanes
}  // namespace newtop::detail
