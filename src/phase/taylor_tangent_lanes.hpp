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
      // the lanes: the terms whose tangent coefficients are older first, the newest (δ^[n]) last.
      // Each product added to its sum by a fused multiply-add, the two of a term one after the
      // other; the terms j = 1..n − 1 in two halves, j and n − j together for 0 < j < n − j (the
      // four coefficients of the pair loaded once for both) into the first and the second, then
      // j = n/2 (n even) into the second, then the halves added.
      L P{}, Rs{}, S{}, T{}, Pb{}, Rb{}, Sb{}, Tb{};
      auto add = [](const Rotated& da, const Rotated& xb, const Rotated& xa, const Rotated& db,
                    L& sum_p, L& rs, L& sum_s, L& sum_t) {
        sum_p = F::fma(xa.w1, db.w2, F::fma(da.w1, xb.w2, sum_p));
        rs = F::fma(xa.g1, db.g2, F::fma(da.g1, xb.g2, rs));
        sum_s = F::fma(xa.g1, db.w2, F::fma(da.g1, xb.w2, sum_s));
        sum_t = F::fma(xa.g2, db.w1, F::fma(da.g2, xb.w1, sum_t));
      };
      if (n == 0) {
        add(d, X[0], X[0], d, P, Rs, S, T);
      } else {
        const int last_pair = (n - 1) / 2;
        for (int j = 1; j <= last_pair; ++j) {
          add(D[j], X[n - j], X[j], D[n - j], P, Rs, S, T);
          add(D[n - j], X[j], X[n - j], D[j], Pb, Rb, Sb, Tb);
        }
        if (n % 2 == 0) add(D[n / 2], X[n / 2], X[n / 2], D[n / 2], Pb, Rb, Sb, Tb);
        P += Pb;
        Rs += Rb;
        S += Sb;
        T += Tb;
        add(D[0], X[n], X[n], D[0], P, Rs, S, T);  // j = 0's first product and j = n's second
        add(d, X[0], X[0], d, P, Rs, S, T);        // j = n's first product and j = 0's second
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
