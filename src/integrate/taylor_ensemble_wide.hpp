#pragma once
// The Taylor ensemble's recurrences for 32 vector registers (AVX-512; private to src/integrate):
// taylor_ensemble_kernel.hpp's expand with the three components at once. There each component
// loads its four coefficients of orders j and n − j for its eight sums; here the twelve
// coefficients of orders j and n − j are loaded once for the 24 sums of the three components
// (twelve in registers, the other half of each sum in a second pass), which halves the loads and
// gives the processor twelve independent chains of additions instead of eight. Each sum adds the
// same products in the same order as there (and as taylor_recurrences.hpp's expand_lanes): the
// same bits.

#include "taylor_ensemble_kernel.hpp"

namespace newtop::detail::taylor_ensemble_simd {

// pair(a, c) (taylor_ensemble_kernel.hpp) for the three components.
template <class F, class V>
[[gnu::always_inline]] inline void pair3(const V (&wa)[3], const V (&ga)[3], const V (&wc)[3],
                                         const V (&gc)[3], Sums<V> (&z)[3]) {
  pair<F>(wa, ga, wc, gc, 1, 2, z[0]);
  pair<F>(wa, ga, wc, gc, 2, 0, z[1]);
  pair<F>(wa, ga, wc, gc, 0, 1, z[2]);
}

template <class V, int L, class F>
void expand_wide(const double* consts, const double* x, int order, double* series) {
  const LaneConstants<V, L> q(consts);
  V w[K][3], g[K][3];  // ω^[n], γ^[n]
  start_series(q, x, series, w[0], g[0]);
  for (int n = 0; n < order; ++n) {
    const int last_pair = (n - 1) / 2;
    const double inv = kInverse[static_cast<std::size_t>(n)];
    double* next = series + 6 * (n + 1) * L;
    // expand's two halves of each sum: the odd j (and a last odd j alone), then the even j and
    // the term j = n/2.
    Sums<V> a[3], bsum[3];
    for (int j = 1; j <= last_pair; j += 2) pair3<F>(w[j], g[j], w[n - j], g[n - j], a);
    for (int j = 2; j <= last_pair; j += 2) pair3<F>(w[j], g[j], w[n - j], g[n - j], bsum);
    if (n % 2 == 0 && n > 0) {
      single<F>(w[n / 2], g[n / 2], 1, 2, bsum[0]);
      single<F>(w[n / 2], g[n / 2], 2, 0, bsum[1]);
      single<F>(w[n / 2], g[n / 2], 0, 1, bsum[2]);
    }
    for (int c = 0; c < 3; ++c) {
      a[c].p += bsum[c].p;
      a[c].rs += bsum[c].rs;
      a[c].s += bsum[c].s;
      a[c].t += bsum[c].t;
    }
    if (n == 0) {
      single<F>(w[0], g[0], 1, 2, a[0]);
      single<F>(w[0], g[0], 2, 0, a[1]);
      single<F>(w[0], g[0], 0, 1, a[2]);
    } else {
      pair3<F>(w[0], g[0], w[n], g[n], a);
    }
    for (int c = 0; c < 3; ++c)
      finish_component(q, c, w[n], g[n], a[c], inv, next, w[n + 1], g[n + 1]);
  }
}

}  // namespace newtop::detail::taylor_ensemble_simd
