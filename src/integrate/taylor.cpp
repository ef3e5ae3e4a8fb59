// Taylor's method on the Euler–Poisson equations of the quadratic field: the recurrences of the
// coefficients and the step (newtop/integrate/taylor.hpp).
//
// With ω = I⁻¹(m − k) the equations are ṁ = (Iω) × ω + k × ω + γ × b + λ γ × Iγ, γ̇ = γ × ω,
// q̇ = ½ q ⊗ (0, ω) (b = M g r0), and (Iω) × ω = (B − C) ω₂ω₃ e₁ + cyclic, γ × Iγ = (C − B) γ₂γ₃ e₁
// + cyclic. The coefficient n + 1 of each is 1/(n + 1) times the coefficient n of its right-hand
// side, whose products are the Cauchy sums Σ_{j=0..n} a^[j] b^[n−j]. Three lanes carry the three
// components, with the operands rotated once (y, z, x) and twice (z, x, y) so that one vector
// product forms ω₂ω₃, ω₃ω₁, ω₁ω₂ together. Lane-wise operations in a fixed order and no
// contraction into fused multiply-adds (CMakeLists.txt): the same bits on every instruction set.

#include "newtop/integrate/taylor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "taylor_lanes.hpp"

namespace newtop {
namespace detail {
namespace {

using namespace taylor_lanes;

// The coefficients 1..order from those of order 0 in s, in lanes of type L.
template <class L>
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
    L P{}, Rs{}, S{}, T{}, Pb{}, Rb{}, Sb{}, Tb{};
    auto pair = [](const Rotated& a, const Rotated& c, L& sum_p, L& rs, L& sum_s, L& sum_t) {
      sum_p += a.w1 * c.w2 + c.w1 * a.w2;
      rs += a.g1 * c.g2 + c.g1 * a.g2;
      sum_s += a.g1 * c.w2 + c.g1 * a.w2;
      sum_t += a.g2 * c.w1 + c.g2 * a.w1;
    };
    auto single = [](const Rotated& a, L& sum_p, L& rs, L& sum_s, L& sum_t) {
      sum_p += a.w1 * a.w2;
      rs += a.g1 * a.g2;
      sum_s += a.g1 * a.w2;
      sum_t += a.g2 * a.w1;
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

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] void expand_avx2(const TaylorModel& p, int order, TaylorSeries& s) {
  expand_lanes<V4>(p, order, s);
}
#endif

void expand_kernel(const TaylorModel& p, int order, TaylorSeries& s, bool baseline) {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2 && !baseline) return expand_avx2(p, order, s);
#endif
  expand_lanes<Pair4>(p, order, s);
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
