#pragma once
/// \file
/// Dormand and Prince's Runge–Kutta pair 8(5,3) (dop853_tableau.hpp) with Hairer's error control
/// and its continuous extension of order 7: newtop's adaptive method of order 8. Per accepted step
/// 12 evaluations of f (the end point's f is the next step's first stage); the error of the step
/// is estimated from the embedded solutions of orders 5 and 3 together (Hairer, Nørsett & Wanner,
/// Solving ODEs I, §II.10): with sc_i = abs_tol + rel_tol max(|y0_i|, |y1_i|),
/// e5 = Σ (h (Σ_j e5_j k_j)_i / sc_i)², e3 = Σ (h (Σ_j (b_j − b̂_j) k_j)_i / sc_i)²,
/// err = e5 / sqrt(n (e5 + 0.01 e3)) — a step is accepted when err ≤ 1, and the next step is
/// h err^(−1/8) · 0.9, changed by a factor between 1/3 and 6 (not increased after a rejection).
/// A trial that gives NaN or inf is rejected and retried kNonFiniteShrink times shorter.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>

#include "newtop/integrate/dop853_tableau.hpp"
#include "newtop/integrate/runge_kutta.hpp"

#if defined(__GNUC__) && !defined(__clang__)
#define NEWTOP_DOP853_SCALAR __attribute__((optimize("no-tree-vectorize")))
#else
#define NEWTOP_DOP853_SCALAR
#endif

namespace newtop {
namespace detail {

/// The pair on one ODE state type Y (std::array of n numbers) and any system sys(y, dydt, t).
template <class Y>
class Dop853Core {
  static constexpr std::size_t n = std::tuple_size_v<Y>;

 public:
  static constexpr int kOrder = 8;
  static constexpr double kSafety = 0.9, kMinFactor = 1.0 / 3.0, kMaxFactor = 6.0;

  Dop853Core(double abs_tol, double rel_tol) : abs_tol_(abs_tol), rel_tol_(rel_tol) {}

  /// The first trial step from (t0, y0) towards t0 + span (starting_step of order 8).
  template <class Sys>
  double initial_step(const Sys& sys, const Y& y0, double t0, double span) {
    at_point(sys, y0, t0);
    return starting_step(sys, y_, f_, t0, span, abs_tol_, rel_tol_, kOrder);
  }

  /// One trial step of dt from (t, y): on acceptance y and t advance (y to the method's own end
  /// point, which point() then holds). dt becomes the next step either way.
  template <class Sys>
  bool try_step(const Sys& sys, Y& y, double& t, double& dt) {
    namespace T = dop853;
    at_point(sys, y, t);
    const double h = dt;
    Y y1;
    advance(sys, t, h, y1);
    // The two error estimates, in the weights 1/sc_i.
    const auto& k = k_;
    const auto& e = T::e5;
    double e5 = 0.0, e3 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 1.0 / (abs_tol_ + rel_tol_ * std::max(std::abs(y_[i]), std::abs(y1[i])));
      const double err5 = (e[0] * k[0][i] + e[5] * k[5][i] + e[6] * k[6][i] + e[7] * k[7][i] +
                           e[8] * k[8][i] + e[9] * k[9][i] + e[10] * k[10][i] + e[11] * k[11][i]) *
                          w;
      const double err3 =
          (bk_[i] - T::bhh[0] * k[0][i] - T::bhh[1] * k[8][i] - T::bhh[2] * k[11][i]) * w;
      e5 += err5 * err5;
      e3 += err3 * err3;
    }
    double deno = e5 + 0.01 * e3;
    if (deno <= 0.0) deno = 1.0;
    const double err = std::abs(h) * e5 / std::sqrt(static_cast<double>(n) * deno);
    if (!std::isfinite(err) || !all_finite(y1)) {
      dt = kNonFiniteShrink * h;
      rejected_ = true;
      return false;
    }
    const double grow = std::sqrt(std::sqrt(std::sqrt(err))) / kSafety;  // err^(1/8); h / grow
    if (err > 1.0) {
      dt = h / std::min(grow, 1.0 / kMinFactor);
      rejected_ = true;
      return false;
    }
    double h_new = h / std::clamp(grow, 1.0 / kMaxFactor, 1.0 / kMinFactor);
    if (rejected_) h_new = std::abs(h_new) < std::abs(h) ? h_new : h;
    rejected_ = false;
    // Accepted: keep the step for the continuous extension; f at the end is the next first stage.
    y0_ = y_;
    y1_ = y1;
    t0_ = t;
    h_ = h;
    t += h;
    sys(y1_, k_[12], t);
    y_ = y1_;
    f_ = k[12];
    has_f_ = true;
    ++step_id_;
    y = y_;
    dt = h_new;
    return true;
  }

  /// One step of the order-8 formula from (t, y) with no error control: the map every accepted
  /// step applies (event location lands on the method's own solution with it); f(y) evaluated
  /// afresh.
  template <class Sys>
  Y step(const Sys& sys, const Y& y, double t, double h) {
    has_f_ = false;
    at_point(sys, y, t);
    Y y1;
    advance(sys, t, h, y1);
    return y1;
  }

  /// The current point and f there (after an accepted step: its end); a caller may rescale both
  /// (the attitude's renormalisation) before the next step.
  Y& point() { return y_; }
  Y& derivative() { return f_; }

  /// The continuous extension of order 7 of the last accepted step at t (3 more evaluations of f
  /// on first use per step).
  template <class Sys>
  Y dense(const Sys& sys, double t) {
    if (dense_id_ != step_id_) build_dense(sys);
    const double s = (t - t0_) / h_, s1 = 1.0 - s;
    const auto& F = dense_;
    Y y;
    for (std::size_t i = 0; i < n; ++i) {
      y[i] =
          y0_[i] + s * (F[0][i] +
                        s1 * (F[1][i] +
                              s * (F[2][i] +
                                   s1 * (F[3][i] + s * (F[4][i] + s1 * (F[5][i] + s * F[6][i]))))));
    }
    return y;
  }

 private:
  /// The stages k_1 … k_11 of a step of h from (t, y_) (k_0 = f_) and the order-8 end point y1.
  /// Scalar code (NEWTOP_DOP853_SCALAR): each stage reads the f just written component by
  /// component, which two-lane loads cannot take from the store buffer (on GCC 12, x86-64: 275 →
  /// 217 ns per step, build/bench/bench_steppers dop853_accepted_step).
  template <class Sys>
  NEWTOP_DOP853_SCALAR void advance(const Sys& sys, double t, double h, Y& y1) {
    namespace T = dop853;
    auto& k = k_;
    k[0] = f_;
    Y z;
    // Stage s at y + h Σ_{j<s} a_sj k_j, the newest term added last (with h a_s,s−1 formed
    // before it arrives) to keep the chain from one evaluation to the next short.
    auto stage = [&](int s, auto&& earlier) {
      const double h_last = h * T::a[s][s - 1];
      for (std::size_t i = 0; i < n; ++i) z[i] = (y_[i] + h * earlier(i)) + h_last * k[s - 1][i];
      sys(z, k[s], t + T::c[s] * h);
    };
    const auto& a = T::a;
    for (std::size_t i = 0; i < n; ++i) z[i] = y_[i] + (h * a[1][0]) * k[0][i];
    sys(z, k[1], t + T::c[1] * h);
    stage(2, [&](std::size_t i) { return a[2][0] * k[0][i]; });
    stage(3, [&](std::size_t i) { return a[3][0] * k[0][i]; });
    stage(4, [&](std::size_t i) { return a[4][0] * k[0][i] + a[4][2] * k[2][i]; });
    stage(5, [&](std::size_t i) { return a[5][0] * k[0][i] + a[5][3] * k[3][i]; });
    stage(6,
          [&](std::size_t i) { return a[6][0] * k[0][i] + a[6][3] * k[3][i] + a[6][4] * k[4][i]; });
    stage(7, [&](std::size_t i) {
      return a[7][0] * k[0][i] + a[7][3] * k[3][i] + a[7][4] * k[4][i] + a[7][5] * k[5][i];
    });
    stage(8, [&](std::size_t i) {
      return a[8][0] * k[0][i] + a[8][3] * k[3][i] + a[8][4] * k[4][i] + a[8][5] * k[5][i] +
             a[8][6] * k[6][i];
    });
    stage(9, [&](std::size_t i) {
      return a[9][0] * k[0][i] + a[9][3] * k[3][i] + a[9][4] * k[4][i] + a[9][5] * k[5][i] +
             a[9][6] * k[6][i] + a[9][7] * k[7][i];
    });
    stage(10, [&](std::size_t i) {
      return a[10][0] * k[0][i] + a[10][3] * k[3][i] + a[10][4] * k[4][i] + a[10][5] * k[5][i] +
             a[10][6] * k[6][i] + a[10][7] * k[7][i] + a[10][8] * k[8][i];
    });
    stage(11, [&](std::size_t i) {
      return a[11][0] * k[0][i] + a[11][3] * k[3][i] + a[11][4] * k[4][i] + a[11][5] * k[5][i] +
             a[11][6] * k[6][i] + a[11][7] * k[7][i] + a[11][8] * k[8][i] + a[11][9] * k[9][i];
    });
    const auto& b = T::b;
    for (std::size_t i = 0; i < n; ++i) {
      bk_[i] = b[0] * k[0][i] + b[5] * k[5][i] + b[6] * k[6][i] + b[7] * k[7][i] + b[8] * k[8][i] +
               b[9] * k[9][i] + b[10] * k[10][i] + b[11] * k[11][i];
      y1[i] = y_[i] + h * bk_[i];
    }
  }

  template <class Sys>
  void at_point(const Sys& sys, const Y& y, double t) {
    if (has_f_ && y == y_) return;
    y_ = y;
    sys(y_, f_, t);
    has_f_ = true;
  }

  template <class Sys>
  void build_dense(const Sys& sys) {
    namespace T = dop853;
    auto& k = k_;
    const double h = h_;
    for (int s = T::kStages + 1; s < T::kExtendedStages; ++s) {
      Y z;
      for (std::size_t i = 0; i < n; ++i) {
        double sum = 0.0;
        for (int j = 0; j < s; ++j) sum += T::a[s][j] * k[j][i];
        z[i] = y0_[i] + h * sum;
      }
      sys(z, k[s], t0_ + T::c[s] * h);
    }
    auto& F = dense_;
    for (std::size_t i = 0; i < n; ++i) {
      const double dy = y1_[i] - y0_[i];
      F[0][i] = dy;
      F[1][i] = h * k[0][i] - dy;
      F[2][i] = 2.0 * dy - h * (k[12][i] + k[0][i]);
      for (int r = 0; r < 4; ++r) {
        double sum = 0.0;
        for (int j = 0; j < T::kExtendedStages; ++j) sum += T::d[r][j] * k[j][i];
        F[3 + r][i] = h * sum;
      }
    }
    dense_id_ = step_id_;
  }

  double abs_tol_, rel_tol_;
  Y y_{}, f_{};  // the current point and f there (when has_f_)
  bool has_f_ = false, rejected_ = false;
  std::array<Y, dop853::kExtendedStages> k_{};
  Y bk_{};         // Σ b_j k_j of the last trial
  Y y0_{}, y1_{};  // the last accepted step: its start and its own (unprojected) end
  double t0_ = 0.0, h_ = 0.0;
  std::array<Y, 7> dense_{};
  std::int64_t step_id_ = 0, dense_id_ = -1;
};

/// Dop853Core on the Euler–Poisson equations of one state type (Y = OdeState for State,
/// OrientedOdeState for OrientedState), in AdaptivePair's interface; with an attitude q is
/// renormalised after each accepted step and in the continuous extension.
template <class Y>
class Dop853OnModel {
  static constexpr bool kWithAttitude = std::is_same_v<Y, OrientedOdeState>;
  using X = std::conditional_t<kWithAttitude, OrientedState, State>;

 public:
  Dop853OnModel(double abs_tol, double rel_tol) : core_(abs_tol, rel_tol) {}

  template <Field F>
  double initial_step(const BasicModel<F>& model, const X& x, double t0, double t1) {
    return core_.initial_step(OdeSystem<F, Y>{&model}, to_ode(x), t0, t1 - t0);
  }

  template <Field F>
  bool try_step(const BasicModel<F>& model, X& x, double& t, double& dt) {
    Y y = to_ode(x);
    if (!core_.try_step(OdeSystem<F, Y>{&model}, y, t, dt)) return false;
    if constexpr (kWithAttitude) {
      // q̇ is linear in q: f at the renormalised point is the same rescaling.
      projection_ = std::max(projection_, renormalise(core_.point(), &core_.derivative()));
    }
    x = from_ode(core_.point());
    return true;
  }

  template <Field F>
  X dense_state(const BasicModel<F>& model, double t) {
    Y y = core_.dense(OdeSystem<F, Y>{&model}, t);
    if constexpr (kWithAttitude) renormalise(y);
    return from_ode(y);
  }

  double attitude_projection() const { return projection_; }

 private:
  Dop853Core<Y> core_;
  double projection_ = 0.0;
};

}  // namespace detail

/// Dormand–Prince 8(5,3) (detail::Dop853Core) on the Euler–Poisson equations: the AdaptiveStepper
/// and DenseStepper of order 8. A state with an attitude runs the pair on the ten numbers
/// (m, γ, q), q renormalised after each accepted step (the continuous extension is the method's,
/// of the unprojected end point, renormalised).
class Dop853Stepper : public detail::AdaptivePair<detail::Dop853OnModel<OdeState>,
                                                  detail::Dop853OnModel<OrientedOdeState>,
                                                  detail::Dop853Core<OdeState>::kOrder> {
  using Base =
      detail::AdaptivePair<detail::Dop853OnModel<OdeState>, detail::Dop853OnModel<OrientedOdeState>,
                           detail::Dop853Core<OdeState>::kOrder>;

 public:
  using Base::Base;
};

/// Dop853Core on the state of another model, whose odeint numbers Y OdeBinding<M, Y> binds (as
/// EmbeddedRkOn for odeint's pairs): the same AdaptiveStepper and DenseStepper, error control and
/// continuous extension, on any model that brings its right-hand side.
template <class Y>
class Dop853On {
  template <class M>
  using X = typename OdeBinding<M, Y>::state_type;
  template <class M>
  using Sys = typename OdeBinding<M, Y>::system;

 public:
  Dop853On(double abs_tol, double rel_tol) : core_(abs_tol, rel_tol) {}
  int order() const { return detail::Dop853Core<Y>::kOrder; }

  template <class M>
  double initial_step(const M& model, const X<M>& x, double t0, double t1) {
    return core_.initial_step(Sys<M>{&model}, OdeBinding<M, Y>::to(x), t0, t1 - t0);
  }
  template <class M>
  bool try_step(const M& model, X<M>& x, double& t, double& dt) {
    Y y = OdeBinding<M, Y>::to(x);
    if (!core_.try_step(Sys<M>{&model}, y, t, dt)) return false;
    x = OdeBinding<M, Y>::from(core_.point());
    return true;
  }
  template <class M>
  X<M> dense_state(const M& model, double t) {
    return OdeBinding<M, Y>::from(core_.dense(Sys<M>{&model}, t));
  }
  /// One step of the order-8 formula from (t, x) by h without error control.
  template <class M>
  X<M> formula_step(const M& model, const X<M>& x, double t, double h) {
    return OdeBinding<M, Y>::from(core_.step(Sys<M>{&model}, OdeBinding<M, Y>::to(x), t, h));
  }

 private:
  detail::Dop853Core<Y> core_;
};

}  // namespace newtop

#undef NEWTOP_DOP853_SCALAR
