#pragma once
// Taylor's recurrences of the state (taylor.cpp; private to the library), in lanes of either kind
// (taylor_lanes.hpp): instantiated with 2 × 2 lanes in taylor.cpp and with 4-lane AVX2 vectors in
// taylor_avx2.cpp, which is compiled for AVX2 and FMA (CMakeLists.txt) and run only where the
// processor has both.

#include "taylor_lanes.hpp"

namespace newtop::detail {

/// The coefficients 1..order of s from its coefficient 0 in 4-lane AVX2 vectors (taylor_avx2.cpp).
void taylor_expand_avx2(const TaylorModel& p, int order, TaylorSeries& s);

namespace taylor_lanes {

// The coefficients 1..order from those of order 0 in s, in lanes of type L; F::fma(a, b, c) is
// a·b + c rounded once, lane by lane.
template <class L, class F>
[[gnu::always_inline]] inline void expand_lanes(const TaylorModel& p, int order, TaylorSeries& s) {
  using O = LaneOps<L>;
  struct Rotated {
    L w1, w2, g1, g2;  // ω and γ rotated once and twice
  };
  Rotated R[K];
  L W[K], Q[K], Q1[K], Q2[K], Qw[K];
  const L inv_i = O::load(p.inv_i), k = O::load(p.k), b = O::load(p.b), d_spin = O::load(p.d_spin),
          d_field = O::load(p.d_field);
  const L k1 = O::rot1(k), k2 = O::rot2(k), b1 = O::rot1(b), b2 = O::rot2(b);
  W[0] = (O::load(s.m[0]) - k) * inv_i;
  L G = O::load(s.gamma[0]);
  if (s.attitude) Q[0] = O::load(s.q[0]);
  for (int n = 0; n < order; ++n) {
    Rotated& r = R[n];
    r = {O::rot1(W[n]), O::rot2(W[n]), O::rot1(G), O::rot2(G)};
    // Σ_j ω₂ω₃ (P), γ₂γ₃ (Rs), γ₂ω₃ and γ₃ω₂ (S, T), cyclic in the lanes, the terms j and n − j
    // together (the four coefficients loaded once for the two): the pairs 0 < j < n − j first, in
    // two interleaved halves to shorten the chains of additions, then j = n/2 (n even), then the
    // pair that holds the newest coefficient (j = 0, n), so that only it waits for it.
    // Each product is added to its sum by a fused multiply-add (one rounding), the two of a pair
    // one after the other.
    L P{}, Rs{}, S{}, T{}, Pb{}, Rb{}, Sb{}, Tb{};
    auto pair = [](const Rotated& a, const Rotated& c, L& sum_p, L& rs, L& sum_s, L& sum_t) {
      sum_p = F::fma(c.w1, a.w2, F::fma(a.w1, c.w2, sum_p));
      rs = F::fma(c.g1, a.g2, F::fma(a.g1, c.g2, rs));
      sum_s = F::fma(c.g1, a.w2, F::fma(a.g1, c.w2, sum_s));
      sum_t = F::fma(c.g2, a.w1, F::fma(a.g2, c.w1, sum_t));
    };
    auto single = [](const Rotated& a, L& sum_p, L& rs, L& sum_s, L& sum_t) {
      sum_p = F::fma(a.w1, a.w2, sum_p);
      rs = F::fma(a.g1, a.g2, rs);
      sum_s = F::fma(a.g1, a.w2, sum_s);
      sum_t = F::fma(a.g2, a.w1, sum_t);
    };
    const int last_pair = (n - 1) / 2;
    int j = 1;
    for (; j + 1 <= last_pair; j += 2) {
      pair(R[j], R[n - j], P, Rs, S, T);
      pair(R[j + 1], R[n - j - 1], Pb, Rb, Sb, Tb);
    }
    if (j == last_pair) pair(R[j], R[n - j], P, Rs, S, T);
    if (n % 2 == 0 && n > 0) single(R[n / 2], Pb, Rb, Sb, Tb);
    P += Pb;
    Rs += Rb;
    S += Sb;
    T += Tb;
    if (n == 0) {
      single(r, P, Rs, S, T);
    } else {
      pair(R[0], r, P, Rs, S, T);
    }
    const double inv = kInverse[static_cast<std::size_t>(n)];
    // m^[n+1] and ω^[n+1] = I⁻¹ m^[n+1].
    const L linear = (k1 * r.w2 - k2 * r.w1) + (r.g1 * b2 - r.g2 * b1);
    const L m_next = (d_spin * P + d_field * Rs + linear) * inv;
    O::store(s.m[n + 1], m_next);
    W[n + 1] = m_next * inv_i;
    G = (S - T) * inv;
    O::store(s.gamma[n + 1], G);
    if (s.attitude) {
      // q ⊗ (0, u) = (w u + v × u, −v·u) in lanes (x, y, z | w).
      Q1[n] = O::rot1(Q[n]);
      Q2[n] = O::rot2(Q[n]);
      Qw[n] = O::splat3(O::lane(Q[n], 3));
      // Σ_i q^[i] ⊗ (0, ω^[n−i]): i = 1..n − 1 first, the newest coefficients (i = 0, n) last.
      L A{}, X{}, Y{}, D{};
      auto add = [&](int i) {
        A += Qw[i] * W[n - i];
        X += Q1[i] * R[n - i].w2;
        Y += Q2[i] * R[n - i].w1;
        D += Q[i] * W[n - i];
      };
      for (int i = 1; i < n; ++i) add(i);
      add(0);
      if (n > 0) add(n);
      L q_next = (A + X - Y) * (0.5 * inv);
      O::set_w(q_next, -(O::lane(D, 0) + O::lane(D, 1) + O::lane(D, 2)) * (0.5 * inv));
      Q[n + 1] = q_next;
      O::store(s.q[n + 1], q_next);
    }
  }
}

}  // namespace taylor_lanes
}  // namespace newtop::detail
