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
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace newtop {
namespace detail {
namespace {

using V = double __attribute__((vector_size(32)));
using Lanes = TaylorSeries::Lanes;

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define NEWTOP_TAYLOR_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define NEWTOP_TAYLOR_KERNEL
#endif

#define NEWTOP_ROT1(a) __builtin_shufflevector(a, a, 1, 2, 0, 3)  // (y, z, x, w)
#define NEWTOP_ROT2(a) __builtin_shufflevector(a, a, 2, 0, 1, 3)  // (z, x, y, w)

inline V load(const Lanes& a) {
  V v;
  std::memcpy(&v, a.data(), sizeof v);
  return v;
}

inline void store(Lanes& a, const V& v) { std::memcpy(a.data(), &v, sizeof v); }

constexpr int K = TaylorSeries::kMaxOrder + 1;

// The coefficients 1..order from those of order 0 in s.
NEWTOP_TAYLOR_KERNEL void expand_kernel(const TaylorModel& p, int order, TaylorSeries& s) {
  V W[K], W1[K], W2[K], G[K], G1[K], G2[K], Q[K], Q1[K], Q2[K], Qw[K];
  const V inv_i = load(p.inv_i), k = load(p.k), b = load(p.b), d_spin = load(p.d_spin),
          d_field = load(p.d_field);
  const V k1 = NEWTOP_ROT1(k), k2 = NEWTOP_ROT2(k), b1 = NEWTOP_ROT1(b), b2 = NEWTOP_ROT2(b);
  W[0] = (load(s.m[0]) - k) * inv_i;
  G[0] = load(s.gamma[0]);
  if (s.attitude) Q[0] = load(s.q[0]);
  for (int n = 0; n < order; ++n) {
    W1[n] = NEWTOP_ROT1(W[n]);
    W2[n] = NEWTOP_ROT2(W[n]);
    G1[n] = NEWTOP_ROT1(G[n]);
    G2[n] = NEWTOP_ROT2(G[n]);
    // Σ_j ω₂ω₃ (P), γ₂γ₃ (R), γ₂ω₃ and γ₃ω₂ (S, T), cyclic in the lanes; two interleaved halves
    // (even and odd j) shorten the chains of additions.
    V P{}, R{}, S{}, T{}, Pb{}, Rb{}, Sb{}, Tb{};
    int j = 0;
    for (; j + 1 <= n; j += 2) {
      P += W1[j] * W2[n - j];
      R += G1[j] * G2[n - j];
      S += G1[j] * W2[n - j];
      T += G2[j] * W1[n - j];
      Pb += W1[j + 1] * W2[n - j - 1];
      Rb += G1[j + 1] * G2[n - j - 1];
      Sb += G1[j + 1] * W2[n - j - 1];
      Tb += G2[j + 1] * W1[n - j - 1];
    }
    if (j == n) {
      P += W1[n] * W2[0];
      R += G1[n] * G2[0];
      S += G1[n] * W2[0];
      T += G2[n] * W1[0];
    }
    P += Pb;
    R += Rb;
    S += Sb;
    T += Tb;
    const double inv = 1.0 / static_cast<double>(n + 1);
    const V m_next =
        (d_spin * P + d_field * R + (k1 * W2[n] - k2 * W1[n]) + (G1[n] * b2 - G2[n] * b1)) * inv;
    store(s.m[n + 1], m_next);
    W[n + 1] = m_next * inv_i;
    G[n + 1] = (S - T) * inv;
    store(s.gamma[n + 1], G[n + 1]);
    if (s.attitude) {
      // q ⊗ (0, u) = (w u + v × u, −v·u) in lanes (x, y, z | w).
      Q1[n] = NEWTOP_ROT1(Q[n]);
      Q2[n] = NEWTOP_ROT2(Q[n]);
      const double w = Q[n][3];
      Qw[n] = V{w, w, w, 0.0};
      V A{}, X{}, Y{}, D{};
      for (int i = 0; i <= n; ++i) {
        A += Qw[i] * W[n - i];
        X += Q1[i] * W2[n - i];
        Y += Q2[i] * W1[n - i];
        D += Q[i] * W[n - i];
      }
      V q_next = (A + X - Y) * (0.5 * inv);
      q_next[3] = -(D[0] + D[1] + D[2]) * (0.5 * inv);
      Q[n + 1] = q_next;
      store(s.q[n + 1], q_next);
    }
  }
}

double norm_inf(const Lanes& a, int lanes) {
  double n = 0.0;
  for (int i = 0; i < lanes; ++i) {
    const double v = std::abs(a[static_cast<std::size_t>(i)]);
    if (!(v <= n)) n = v;  // NaN propagates
  }
  return n;
}

double nan_max(double a, double b) { return a >= b || std::isnan(a) ? a : b; }

double coefficient_norm(const TaylorSeries& s, int n) {
  const auto i = static_cast<std::size_t>(n);
  const double r = nan_max(norm_inf(s.m[i], 3), norm_inf(s.gamma[i], 3));
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
}

void taylor_expand(const TaylorModel& model, const State& x, const Quaternion* q, int order,
                   TaylorSeries& s) {
  s.order = order;
  s.attitude = q != nullptr;
  s.m[0] = {x.m.x(), x.m.y(), x.m.z(), 0.0};
  s.gamma[0] = {x.gamma.x(), x.gamma.y(), x.gamma.z(), 0.0};
  if (q != nullptr) s.q[0] = {q->x(), q->y(), q->z(), q->w()};
  expand_kernel(model, order, s);
}

State taylor_state(const TaylorSeries& s, double h) {
  State x;
  for (int i = 0; i < 3; ++i) {
    const auto c = static_cast<std::size_t>(i);
    double m = s.m[static_cast<std::size_t>(s.order)][c];
    double g = s.gamma[static_cast<std::size_t>(s.order)][c];
    for (int n = s.order - 1; n >= 0; --n) {
      m = m * h + s.m[static_cast<std::size_t>(n)][c];
      g = g * h + s.gamma[static_cast<std::size_t>(n)][c];
    }
    x.m[i] = m;
    x.gamma[i] = g;
  }
  return x;
}

Quaternion taylor_attitude(const TaylorSeries& s, double h) {
  Lanes r = s.q[static_cast<std::size_t>(s.order)];
  for (int n = s.order - 1; n >= 0; --n) {
    for (std::size_t c = 0; c < 4; ++c) r[c] = r[c] * h + s.q[static_cast<std::size_t>(n)][c];
  }
  return Quaternion(r[3], r[0], r[1], r[2]);
}

double taylor_step(const TaylorSeries& s, double abs_tol, double rel_tol) {
  const int p = s.order;
  const double eps = std::max(abs_tol, rel_tol * coefficient_norm(s, 0));
  double h = std::numeric_limits<double>::infinity();
  bool found = false;
  for (int n = p; n >= 1 && (!found || n >= p - 1); --n) {
    const double c = coefficient_norm(s, n);
    if (std::isnan(c) || std::isinf(c)) return std::numeric_limits<double>::quiet_NaN();
    if (c > 0.0) {
      h = std::min(h, std::pow(eps / c, 1.0 / n));
      found = true;
    }
  }
  return h * std::exp(-0.7 / (p - 1));
}

int taylor_order(double tol) {
  const double digits = std::abs(std::log(tol));
  if (!std::isfinite(digits)) return 30;
  return std::clamp(static_cast<int>(std::ceil(0.6 * digits)) + 2, 8, 30);
}

}  // namespace detail

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
