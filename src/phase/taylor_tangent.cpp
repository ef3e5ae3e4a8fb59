// Taylor's method on the variational equations of the quadratic field (newtop/phase/
// tangent_taylor.hpp): with δω = I⁻¹ δm,
//
//   δṁ = (B − C)(δω₂ ω₃ + ω₂ δω₃) e₁ + cyclic + k × δω + δγ × b + λ (C − B)(δγ₂ γ₃ + γ₂ δγ₃) e₁
//        + cyclic,   δγ̇ = δγ × ω + γ × δω,
//
// so δx^[n+1] = 1/(n + 1) × the coefficient n of the right-hand side, whose products are the Cauchy
// sums Σ_j (δa^[j] b^[n−j] + a^[j] δb^[n−j]) along the state's series. The lanes and their
// operations are those of taylor.cpp (taylor_lanes.hpp): the same bits on every instruction set.

#include <algorithm>

#include "../integrate/taylor_lanes.hpp"
#include "newtop/phase/tangent_taylor.hpp"

namespace newtop {
namespace detail {
namespace {

using namespace taylor_lanes;

// The coefficients 1..order of each column of ts from its coefficient 0, along s, in lanes L.
template <class L>
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
      L P{}, Rs{}, S{}, T{};
      auto add = [&](const Rotated& da, const Rotated& xb, const Rotated& xa, const Rotated& db) {
        P += da.w1 * xb.w2 + xa.w1 * db.w2;
        Rs += da.g1 * xb.g2 + xa.g1 * db.g2;
        S += da.g1 * xb.w2 + xa.g1 * db.w2;
        T += da.g2 * xb.w1 + xa.g2 * db.w1;
      };
      if (n == 0) {
        add(d, X[0], X[0], d);
      } else {
        for (int j = 1; j < n; ++j) add(D[j], X[n - j], X[j], D[n - j]);
        add(D[0], X[n], X[n], D[0]);  // j = 0's first product and j = n's second
        add(d, X[0], X[0], d);        // j = n's first product and j = 0's second
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

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] void expand_tangent_avx2(const TaylorModel& p, const TaylorSeries& s,
                                                 TaylorTangentSeries& ts) {
  expand_tangent_lanes<V4>(p, s, ts);
}
#endif

}  // namespace

void taylor_expand_tangent(const TaylorModel& model, const TaylorSeries& s, const phase::Tangent& V,
                           TaylorTangentSeries& ts, bool baseline) {
  ts.order = s.order;
  ts.columns = static_cast<int>(V.cols());
  for (Eigen::Index c = 0; c < V.cols(); ++c) {
    const auto i = static_cast<std::size_t>(c);
    ts.m[i][0] = {V(0, c), V(1, c), V(2, c), 0.0};
    ts.gamma[i][0] = {V(3, c), V(4, c), V(5, c), 0.0};
  }
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2 && !baseline) return expand_tangent_avx2(model, s, ts);
#endif
  expand_tangent_lanes<Pair4>(model, s, ts);
}

void taylor_tangent_sum(const TaylorTangentSeries& ts, double h, phase::Tangent& V) {
  for (int c = 0; c < ts.columns; ++c) {
    const auto i = static_cast<std::size_t>(c);
    const State v = sum_series(ts.m[i].data(), ts.gamma[i].data(), ts.order, h);
    V.col(c) << v.m, v.gamma;
  }
}

double taylor_tangent_step(const TaylorSeries& s, const TaylorTangentSeries& ts, double abs_tol,
                           double rel_tol) {
  auto norm = [&](int n) {
    const auto i = static_cast<std::size_t>(n);
    double r = pair_norm(s.m[i], s.gamma[i]);
    for (std::size_t c = 0; c < static_cast<std::size_t>(ts.columns); ++c) {
      r = nan_max(r, pair_norm(ts.m[c][i], ts.gamma[c][i]));
    }
    return r;
  };
  return step_from_norms(s.order, norm, abs_tol, rel_tol);
}

}  // namespace detail

namespace phase {

TangentTaylorStepper::TangentTaylorStepper(double abs_tol, double rel_tol, int order)
    : abs_tol_(abs_tol),
      rel_tol_(rel_tol),
      order_(TaylorStepper(abs_tol, rel_tol, order).order()) {}  // its checks and order rule

void TangentTaylorStepper::expand_state(const QuadraticModel& model, const State& x) {
  if (!params_.of(model)) params_ = detail::TaylorModel(model);
  detail::taylor_expand(params_, x, nullptr, order_, series_);
}

}  // namespace phase
}  // namespace newtop
