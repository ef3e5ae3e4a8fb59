// Taylor's method on the variational equations of the quadratic field (newtop/phase/
// tangent_taylor.hpp): with δω = I⁻¹ δm,
//
//   δṁ = (B − C)(δω₂ ω₃ + ω₂ δω₃) e₁ + cyclic + k × δω + δγ × b + λ (C − B)(δγ₂ γ₃ + γ₂ δγ₃) e₁
//        + cyclic,   δγ̇ = δγ × ω + γ × δω,
//
// so δx^[n+1] = 1/(n + 1) × the coefficient n of the right-hand side, whose products are the Cauchy
// sums Σ_j (δa^[j] b^[n−j] + a^[j] δb^[n−j]) along the state's series (taylor_tangent_lanes.hpp).
// The lanes and their operations are those of taylor.cpp (taylor_lanes.hpp): the same bits on
// every instruction set.

#include <algorithm>

#include "taylor_tangent_lanes.hpp"

namespace newtop {
namespace detail {

using namespace taylor_lanes;

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
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if (avx2 && !baseline) return taylor_expand_tangent_avx2(model, s, ts);
#endif
  expand_tangent_lanes<Pair4, PairFma>(model, s, ts);
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
