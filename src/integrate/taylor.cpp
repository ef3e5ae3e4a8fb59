// Taylor's method on the Euler–Poisson equations of the quadratic field: the recurrences of the
// coefficients and the step (newtop/integrate/taylor.hpp).
//
// With ω = I⁻¹(m − k) the equations are ṁ = (Iω) × ω + k × ω + γ × b + λ γ × Iγ, γ̇ = γ × ω,
// q̇ = ½ q ⊗ (0, ω) (b = M g r0), and (Iω) × ω = (B − C) ω₂ω₃ e₁ + cyclic, γ × Iγ = (C − B) γ₂γ₃ e₁
// + cyclic. The coefficient n + 1 of each is 1/(n + 1) times the coefficient n of its right-hand
// side, whose products are the Cauchy sums Σ_{j=0..n} a^[j] b^[n−j]. Three lanes carry the three
// components, with the operands rotated once (y, z, x) and twice (z, x, y) so that one vector
// product forms ω₂ω₃, ω₃ω₁, ω₁ω₂ together (taylor_recurrences.hpp). Lane-wise operations in a fixed
// order, fused multiply-adds only where the recurrences ask for one and no other contraction
// (CMakeLists.txt): the same bits on every instruction set.

#include "newtop/integrate/taylor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "taylor_recurrences.hpp"

namespace newtop {
namespace detail {
namespace {

using namespace taylor_lanes;

void expand_kernel(const TaylorModel& p, int order, TaylorSeries& s, bool baseline) {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if (avx2 && !baseline) return taylor_expand_avx2(p, order, s);
#endif
  expand_lanes<Pair4, PairFma>(p, order, s);
}

double coefficient_norm(const TaylorSeries& s, int n) {
  const auto i = static_cast<std::size_t>(n);
  const double r = pair_norm(s.m[i], s.gamma[i]);
  return s.attitude ? nan_max(r, norm_inf(s.q[i], 4)) : r;
}

}  // namespace

TaylorModel::TaylorModel(const QuadraticModel& model) {
  const Vec3& I = model.body.inertia();
  const Vec3 b_vec = model.body.mass() * model.field.g * model.body.center_of_mass();
  const double l = model.field.lambda_;
  for (int i = 0; i < 3; ++i) {
    inv_i[static_cast<std::size_t>(i)] = 1.0 / I[i];
    k[static_cast<std::size_t>(i)] = model.body.gyrostat()[i];
    b[static_cast<std::size_t>(i)] = b_vec[i];
  }
  d_spin = {I[1] - I[2], I[2] - I[0], I[0] - I[1], 0.0};
  d_field = {l * (I[2] - I[1]), l * (I[0] - I[2]), l * (I[1] - I[0]), 0.0};
  inertia = I;
  lambda = l;
  set = true;
}

bool TaylorModel::of(const QuadraticModel& model) const {
  if (!set || model.body.inertia() != inertia || model.field.lambda_ != lambda) return false;
  const Vec3 b_vec = model.body.mass() * model.field.g * model.body.center_of_mass();
  for (int i = 0; i < 3; ++i) {
    const auto c = static_cast<std::size_t>(i);
    if (k[c] != model.body.gyrostat()[i] || b[c] != b_vec[i]) return false;
  }
  return true;
}

void taylor_expand(const TaylorModel& model, const State& x, const Quaternion* q, int order,
                   TaylorSeries& s, bool baseline) {
  s.order = order;
  s.attitude = q != nullptr;
  s.m[0] = {x.m.x(), x.m.y(), x.m.z(), 0.0};
  s.gamma[0] = {x.gamma.x(), x.gamma.y(), x.gamma.z(), 0.0};
  if (q != nullptr) s.q[0] = {q->x(), q->y(), q->z(), q->w()};
  expand_kernel(model, order, s, baseline);
}

State taylor_state(const TaylorSeries& s, double h) {
  return taylor_lanes::sum_series(s.m.data(), s.gamma.data(), s.order, h);
}

Quaternion taylor_attitude(const TaylorSeries& s, double h) {
  // As taylor_state: Horner in h² over the even and the odd coefficients, (x, y) and (z, w).
  const double h2 = h * h;
  auto horner = [&](int top) {
    const Lanes& q = s.q[static_cast<std::size_t>(top)];
    V2 lo{q[0], q[1]}, hi{q[2], q[3]};
    for (int n = top - 2; n >= 0; n -= 2) {
      const Lanes& c = s.q[static_cast<std::size_t>(n)];
      lo = lo * h2 + V2{c[0], c[1]};
      hi = hi * h2 + V2{c[2], c[3]};
    }
    return std::array<V2, 2>{lo, hi};
  };
  const int odd = s.order % 2;
  const auto even = horner(s.order - odd), other = horner(s.order - 1 + odd);
  const V2 lo = even[0] + other[0] * h, hi = even[1] + other[1] * h;
  return Quaternion(hi[1], lo[0], lo[1], hi[0]);
}

double taylor_step(const TaylorSeries& s, double abs_tol, double rel_tol) {
  return taylor_lanes::step_from_norms(
      s.order, [&](int n) { return coefficient_norm(s, n); }, abs_tol, rel_tol);
}

double taylor_step_from_norms(const double* norms, int order, double abs_tol, double rel_tol) {
  return taylor_lanes::step_from_norms(
      order, [&](int n) { return norms[n]; }, abs_tol, rel_tol);
}

double taylor_step_log2(double x) { return taylor_math::step_log2(x); }
double taylor_step_exp2(double y) { return taylor_math::step_exp2(y); }

int taylor_order(double tol) {
  const double digits = std::abs(std::log(tol));
  if (!std::isfinite(digits)) return 30;
  return std::clamp(static_cast<int>(std::ceil(0.6 * digits)) + 4, 8, 30);
}

}  // namespace detail

namespace detail::taylor_lanes {

State sum_series(const Lanes* m_n, const Lanes* gamma_n, int order, double h) {
  // Horner in h² over the even and over the odd coefficients (two chains of half the length),
  // in three pairs of lanes, (m₁, m₂), (m₃, γ₁), (γ₂, γ₃).
  struct Six {
    V2 a, b, c;
  };
  auto coefficient = [&](int n) {
    const Lanes &m = m_n[n], &g = gamma_n[n];
    return Six{V2{m[0], m[1]}, V2{m[2], g[0]}, V2{g[1], g[2]}};
  };
  const double h2 = h * h;
  auto horner = [&](int top) {
    Six x = coefficient(top);
    for (int n = top - 2; n >= 0; n -= 2) {
      const Six c = coefficient(n);
      x = {x.a * h2 + c.a, x.b * h2 + c.b, x.c * h2 + c.c};
    }
    return x;
  };
  const int odd = order % 2;  // the highest order is odd
  const Six even = horner(order - odd), other = horner(order - 1 + odd);
  const V2 a = even.a + other.a * h, b = even.b + other.b * h, c = even.c + other.c * h;
  return {Vec3(a[0], a[1], b[0]), Vec3(b[1], c[0], c[1])};
}

}  // namespace detail::taylor_lanes

TaylorStepper::TaylorStepper(double abs_tol, double rel_tol, int order)
    : abs_tol_(abs_tol),
      rel_tol_(rel_tol),
      order_(order > 0 ? order : detail::taylor_order(std::min(abs_tol, rel_tol))) {
  if (!(abs_tol > 0.0) || !(rel_tol > 0.0) || !std::isfinite(abs_tol) || !std::isfinite(rel_tol)) {
    throw InputError("tol: expected finite tolerances > 0 for taylor");
  }
  if (order_ < 2 || order_ > detail::TaylorSeries::kMaxOrder) {
    throw InputError("order: expected a Taylor order in [2, " +
                     std::to_string(detail::TaylorSeries::kMaxOrder) + "], found " +
                     std::to_string(order_));
  }
}

void TaylorStepper::advance(State& x, double h) { x = detail::taylor_state(series_[cur_], h); }

void TaylorStepper::advance(OrientedState& x, double h) {
  static_cast<State&>(x) = detail::taylor_state(series_[cur_], h);
  Quaternion q = detail::taylor_attitude(series_[cur_], h);
  const double n = q.norm();
  projection_ = std::max(projection_, std::abs(n - 1.0));
  q.coeffs() /= n;
  x.q = q;
}

}  // namespace newtop
