#pragma once
/// \file
/// Runge–Kutta methods through Boost.Odeint on the Euler–Poisson right-hand side (docs/model.md
/// §4): classical RK4 (fixed step, the baseline) and the embedded pairs Dormand–Prince 5(4) and
/// Fehlberg 7(8) with absolute and relative tolerances, each with a continuous extension (dense
/// output) of its accepted steps.
///
/// With an attitude (OrientedState) the methods integrate q̇ = ½ q ⊗ (0, ω) beside (m, γ), as the
/// ten numbers (m, γ, q_w, q_x, q_y, q_z) (the error control of the adaptive methods covers q as
/// well), and renormalise q after every step; each stepper reports the largest renormalisation
/// |‖q‖ − 1| it applied (attitude_projection), the drift of ‖q‖ in one step. The ten-number
/// steppers are odeint's same methods on the longer array, built beside the six-number ones, so
/// that a run without an attitude runs exactly the code it ran before.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <type_traits>
// Odeint's steppers copy their (not yet sized) scratch arrays on construction, which GCC 12 flags
// as uninitialized use inside Boost's headers; silence that for Boost's lines only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/dense_output_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "newtop/integrate/concepts.hpp"
#include "newtop/integrate/dense_output.hpp"
#include "newtop/model/attitude.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// The state as odeint sees it: (m1, m2, m3, γ1, γ2, γ3).
using OdeState = std::array<double, 6>;

inline OdeState to_ode(const State& s) {
  return {s.m[0], s.m[1], s.m[2], s.gamma[0], s.gamma[1], s.gamma[2]};
}
inline State from_ode(const OdeState& y) {
  return {Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5])};
}

/// The state with its attitude as odeint sees it: (m1, m2, m3, γ1, γ2, γ3, q_w, q_x, q_y, q_z).
using OrientedOdeState = std::array<double, 10>;

inline OrientedOdeState to_ode(const OrientedState& s) {
  return {s.m[0],     s.m[1],  s.m[2],  s.gamma[0], s.gamma[1],
          s.gamma[2], s.q.w(), s.q.x(), s.q.y(),    s.q.z()};
}
inline OrientedState from_ode(const OrientedOdeState& y) {
  OrientedState s;
  s.m = Vec3(y[0], y[1], y[2]);
  s.gamma = Vec3(y[3], y[4], y[5]);
  s.q = Quaternion(y[6], y[7], y[8], y[9]);
  return s;
}

/// The ODE state for a state type: OdeState for State, OrientedOdeState for OrientedState.
template <class X>
using OdeStateOf = std::conditional_t<kOriented<X>, OrientedOdeState, OdeState>;

/// The Euler–Poisson vector field in odeint's calling convention; on OrientedOdeState with
/// q̇ = ½ q ⊗ (0, ω) beside it.
template <Field F, class Y = OdeState>
struct OdeSystem {
  const BasicModel<F>* model;
  void operator()(const Y& y, Y& dydt, double /*t*/) const {
    if constexpr (std::is_same_v<Y, OdeState>) {
      const State d = rhs(*model, from_ode(y));
      dydt = to_ode(d);
    } else {
      const OrientedState x = from_ode(y);
      const State d = rhs(*model, x);
      const Quaternion dq = attitude_rate(x.q, omega(model->body, x));
      dydt = {d.m[0],     d.m[1], d.m[2], d.gamma[0], d.gamma[1],
              d.gamma[2], dq.w(), dq.x(), dq.y(),     dq.z()};
    }
  }
};

/// The quadratic field's vector field, its per-model numbers formed once per system (a Runge–Kutta
/// step evaluates it 4 to 13 times): 1/I, k, b = M g r0 and λI, so that ω = (m − k) ∘ I⁻¹ and
/// ∂V/∂γ = b + λI ∘ γ cost no division and no product of model constants; ṁ = m × ω + γ × ∂V/∂γ,
/// γ̇ = γ × ω, written out on odeint's arrays. It agrees with rhs(model, x) to a few ulps (ω
/// multiplied by the rounded 1/I, λI rounded once).
template <class Y>
struct OdeSystem<QuadraticField, Y> {
  OdeSystem(const QuadraticModel* m) {  // implicit: built as OdeSystem<F>{&model}
    const Vec3& I = m->body.inertia();
    const double mg = m->body.mass() * m->field.g;
    for (int i = 0; i < 3; ++i) {
      inv_i[i] = 1.0 / I[i];
      k[i] = m->body.gyrostat()[i];
      b[i] = mg * m->body.center_of_mass()[i];
      li[i] = m->field.lambda_ * I[i];
    }
  }
  void operator()(const Y& y, Y& d, double /*t*/) const {
    const double w0 = (y[0] - k[0]) * inv_i[0], w1 = (y[1] - k[1]) * inv_i[1],
                 w2 = (y[2] - k[2]) * inv_i[2];
    const double g0 = b[0] + li[0] * y[3], g1 = b[1] + li[1] * y[4], g2 = b[2] + li[2] * y[5];
    d[0] = (y[1] * w2 - y[2] * w1) + (y[4] * g2 - y[5] * g1);
    d[1] = (y[2] * w0 - y[0] * w2) + (y[5] * g0 - y[3] * g2);
    d[2] = (y[0] * w1 - y[1] * w0) + (y[3] * g1 - y[4] * g0);
    d[3] = y[4] * w2 - y[5] * w1;
    d[4] = y[5] * w0 - y[3] * w2;
    d[5] = y[3] * w1 - y[4] * w0;
    if constexpr (std::is_same_v<Y, OrientedOdeState>) {
      const Quaternion dq = attitude_rate(Quaternion(y[6], y[7], y[8], y[9]), Vec3(w0, w1, w2));
      d[6] = dq.w(), d[7] = dq.x(), d[8] = dq.y(), d[9] = dq.z();
    }
  }

  std::array<double, 3> inv_i{}, k{}, b{}, li{};
};

/// How a model's state meets odeint's numbers Y: the state type, the conversions and the vector
/// field. BasicModel<F> on OdeState (State) and OrientedOdeState (OrientedState) here; a model with
/// a state of its own specialises it for its own numbers, and the embedded pairs run on it.
template <class M, class Y>
struct OdeBinding;

template <Field F, class Y>
struct OdeBinding<BasicModel<F>, Y> {
  using state_type = std::conditional_t<std::is_same_v<Y, OrientedOdeState>, OrientedState, State>;
  using system = OdeSystem<F, Y>;
  static Y to(const state_type& x) { return to_ode(x); }
  static state_type from(const Y& y) { return from_ode(y); }
};

namespace detail {

/// An odeint stepper class template applied to another state type: Stepper<Y0, …> → Stepper<Y>.
template <class S, class Y>
struct RebindState;
template <template <class...> class T, class Y0, class... Rest, class Y>
struct RebindState<T<Y0, Rest...>, Y> {
  using type = T<Y>;
};
template <class S, class Y>
using RebindStateT = typename RebindState<S, Y>::type;

/// Renormalises q in y (indices 6..9); returns |‖q‖ − 1| before it and scales `scaled` (q̇ at y,
/// linear in q) alike when given.
inline double renormalise(OrientedOdeState& y, OrientedOdeState* scaled = nullptr) {
  const double n = std::sqrt(y[6] * y[6] + y[7] * y[7] + y[8] * y[8] + y[9] * y[9]);
  for (int i = 6; i < 10; ++i) y[i] /= n;
  if (scaled) {
    for (int i = 6; i < 10; ++i) (*scaled)[i] /= n;
  }
  return std::abs(n - 1.0);
}

}  // namespace detail

/// Any odeint stepper run at a fixed step (its error estimate, if any, unused); with an attitude,
/// the same method on the ten numbers, q renormalised after each step.
template <class OdeintStepper, int Order>
class OdeintFixedStepper {
 public:
  int order() const { return Order; }
  template <Field F>
  void step(const BasicModel<F>& model, State& x, double h) {
    OdeState y = to_ode(x);
    stepper_.do_step(OdeSystem<F>{&model}, y, 0.0, h);
    x = from_ode(y);
  }
  template <Field F>
  void step(const BasicModel<F>& model, OrientedState& x, double h) {
    OrientedOdeState y = to_ode(x);
    oriented_.do_step(OdeSystem<F, OrientedOdeState>{&model}, y, 0.0, h);
    projection_ = std::max(projection_, detail::renormalise(y));
    x = from_ode(y);
  }
  /// The largest renormalisation |‖q‖ − 1| of the attitude in one step so far.
  double attitude_projection() const { return projection_; }

 private:
  OdeintStepper stepper_;
  detail::RebindStateT<OdeintStepper, OrientedOdeState> oriented_;
  double projection_ = 0.0;
};

/// Classical fourth-order Runge–Kutta, fixed step (odeint's runge_kutta4): the baseline.
using Rk4Stepper = OdeintFixedStepper<boost::numeric::odeint::runge_kutta4<OdeState>, 4>;

namespace detail {

/// The starting step of Hairer, Nørsett & Wanner, Solving ODEs I, §II.4 (their codes' HINIT): with
/// the weights sc_i = abs_tol + rel_tol |y0_i| and the RMS norm, d0 = ‖y0‖, d1 = ‖f(y0)‖, an Euler
/// step h0 = 0.01 d0/d1, d2 = ‖f(y0 + h0 f(y0)) − f(y0)‖ / h0 (a second-derivative estimate), and
/// h = min(100 h0, (0.01 / max(d1, d2))^(1/order)), never beyond |span|.
template <class Sys, class Y>
double starting_step(const Sys& sys, const Y& y0, const Y& f0, double t0, double span,
                     double abs_tol, double rel_tol, int order) {
  auto rms = [&](const auto& term) {
    double s = 0;
    for (std::size_t i = 0; i < y0.size(); ++i) {
      const double v = term(i) / (abs_tol + rel_tol * std::abs(y0[i]));
      s += v * v;
    }
    return std::sqrt(s / static_cast<double>(y0.size()));
  };
  const double d0 = rms([&](std::size_t i) { return y0[i]; });
  const double d1 = rms([&](std::size_t i) { return f0[i]; });
  double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  h0 = std::min(h0, std::abs(span));
  const double dir = span < 0 ? -1.0 : 1.0;
  Y y1, f1;
  for (std::size_t i = 0; i < y0.size(); ++i) y1[i] = y0[i] + dir * h0 * f0[i];
  sys(y1, f1, t0 + dir * h0);
  const double d2 = rms([&](std::size_t i) { return f1[i] - f0[i]; }) / h0;
  if (!std::isfinite(d2)) return h0;
  const double d = std::max(d1, d2);
  const double h1 = d <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / d, 1.0 / order);
  return std::min({100 * h0, h1, std::abs(span)});
}

template <std::size_t N>
inline bool all_finite(const std::array<double, N>& y) {
  return std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); });
}

/// The embedded pair on one state type (odeint's state_type of ErrorStepper: OdeState, or
/// OrientedOdeState for a state with an attitude); EmbeddedRkStepper holds one of each.
template <class ErrorStepper, int Order>
class EmbeddedRkCore {
  using Y = typename ErrorStepper::state_type;
  static constexpr bool kFsal =
      std::is_same_v<typename ErrorStepper::stepper_category,
                     boost::numeric::odeint::explicit_error_stepper_fsal_tag>;
  static constexpr bool kWithAttitude = std::is_same_v<Y, OrientedOdeState>;
  template <class M>
  using X = typename OdeBinding<M, Y>::state_type;
  // The Hermite interpolant works on points of six numbers: a longer state is cut into pieces.
  static constexpr std::size_t kPoint = std::tuple_size_v<HermiteInterpolant::Point>;
  static constexpr std::size_t kPieces = (std::tuple_size_v<Y> + kPoint - 1) / kPoint;

 public:
  EmbeddedRkCore(double abs_tol, double rel_tol)
      : abs_tol_(abs_tol),
        rel_tol_(rel_tol),
        controlled_(boost::numeric::odeint::make_controlled(abs_tol, rel_tol, ErrorStepper())) {}

  int order() const { return Order; }

  template <class M>
  double initial_step(const M& model, const X<M>& x, double t0, double t1) {
    const typename OdeBinding<M, Y>::system sys{&model};
    at_point(sys, OdeBinding<M, Y>::to(x), t0);
    return detail::starting_step(sys, y_, dydt_, t0, t1 - t0, abs_tol_, rel_tol_, Order);
  }

  template <class M>
  bool try_step(const M& model, X<M>& x, double& t, double& dt) {
    const typename OdeBinding<M, Y>::system sys{&model};
    at_point(sys, OdeBinding<M, Y>::to(x), t);
    Y y_new, dydt_new;
    const double t_old = t, dt_tried = dt;
    boost::numeric::odeint::controlled_step_result r;
    if constexpr (kFsal) {
      r = controlled_.try_step(sys, y_, dydt_, t, y_new, dydt_new, dt);
    } else {
      r = controlled_.try_step(sys, y_, dydt_, t, y_new, dt);
    }
    if (r != boost::numeric::odeint::success) return false;
    if (!detail::all_finite(y_new)) {
      t = t_old;
      dt = kNonFiniteShrink * dt_tried;
      return false;
    }
    last_ = {t_old, t, y_, dydt_, y_new, dydt_new};  // the method's own end point, unprojected
    ++step_id_;
    if constexpr (kWithAttitude) {
      // q̇ is linear in q: the derivative at the renormalised point is the same rescaling.
      projection_ = std::max(projection_, renormalise(y_new, kFsal ? &dydt_new : nullptr));
    }
    y_ = y_new;
    dydt_ = dydt_new;
    has_dydt_ = kFsal;  // Fehlberg 7(8): f(y_new) is computed when first needed
    x = OdeBinding<M, Y>::from(y_new);
    return true;
  }

  /// The continuous extension of the last accepted step at t (between its ends); q renormalised.
  template <class M>
  X<M> dense_state(const M& model, double t) {
    Y y;
    if constexpr (kFsal) {
      controlled_.stepper().calc_state(t, y, last_.y_old, last_.dydt_old, last_.t_old, last_.y_new,
                                       last_.dydt_new, last_.t_new);
    } else {
      if (hermite_id_ != step_id_) {
        build_hermite(typename OdeBinding<M, Y>::system{&model});
      }
      const double theta = (t - last_.t_old) / (last_.t_new - last_.t_old);
      for (std::size_t p = 0; p < kPieces; ++p) {
        const HermiteInterpolant::Point u = hermite_[p](theta);
        for (std::size_t i = 0; i < kPoint && p * kPoint + i < y.size(); ++i)
          y[p * kPoint + i] = u[i];
      }
    }
    if constexpr (kWithAttitude) renormalise(y);
    return OdeBinding<M, Y>::from(y);
  }

  double attitude_projection() const { return projection_; }

 private:
  struct AcceptedStep {
    double t_old = 0, t_new = 0;
    Y y_old{}, dydt_old{}, y_new{}, dydt_new{};
  };

  /// Makes (y_, dydt_) the point y and its derivative, evaluating f only for a new point.
  template <class Sys>
  void at_point(const Sys& sys, const Y& y, double t) {
    if (has_dydt_ && y == y_) return;
    y_ = y;
    sys(y_, dydt_, t);
    has_dydt_ = true;
  }

  /// Piece p of a state: its numbers p·6 … p·6 + 5 (zero past the end).
  static HermiteInterpolant::Point piece(const Y& y, std::size_t p) {
    HermiteInterpolant::Point u{};
    for (std::size_t i = 0; i < kPoint && p * kPoint + i < y.size(); ++i) u[i] = y[p * kPoint + i];
    return u;
  }

  template <class Sys>
  void build_hermite(const Sys& sys) {
    AcceptedStep& s = last_;
    const double h = s.t_new - s.t_old;
    at_point(sys, s.y_new, s.t_new);  // shared with the next step's first stage
    s.dydt_new = dydt_;
    constexpr std::array<double, 4> theta{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
    std::array<Y, 4> y{s.y_old, {}, {}, s.y_new}, f{s.dydt_old, {}, {}, s.dydt_new};
    for (int i = 1; i <= 2; ++i) {
      partial_.do_step(sys, s.y_old, s.dydt_old, s.t_old, y[i], theta[i] * h);
      sys(y[i], f[i], s.t_old + theta[i] * h);
    }
    for (auto& fi : f) {
      for (double& v : fi) v *= h;
    }
    for (std::size_t p = 0; p < kPieces; ++p) {
      std::array<HermiteInterpolant::Point, 4> yp, fp;
      for (std::size_t i = 0; i < 4; ++i) yp[i] = piece(y[i], p), fp[i] = piece(f[i], p);
      hermite_[p] = HermiteInterpolant(theta, yp, fp);
    }
    hermite_id_ = step_id_;
  }

  double abs_tol_, rel_tol_;
  typename boost::numeric::odeint::result_of::make_controlled<ErrorStepper>::type controlled_;
  Y y_{}, dydt_{};  // the current point and f there (when has_dydt_)
  bool has_dydt_ = false;
  AcceptedStep last_;
  std::int64_t step_id_ = 0, hermite_id_ = -1;
  ErrorStepper partial_;  // Fehlberg 7(8): the inner nodes of the interpolant
  std::array<HermiteInterpolant, kPieces> hermite_;
  double projection_ = 0.0;
};

/// An adaptive method on both state types, the AdaptiveStepper and DenseStepper that newtop's
/// drivers run: Plain on State, Oriented on OrientedState, each with initial_step(model, x, t0,
/// t1), try_step(model, x, t, dt), dense_state(model, t) and attitude_projection().
template <class Plain, class Oriented, int Order>
class AdaptivePair {
 public:
  AdaptivePair(double abs_tol, double rel_tol)
      : abs_tol_(abs_tol),
        rel_tol_(rel_tol),
        plain_(abs_tol, rel_tol),
        oriented_(abs_tol, rel_tol) {}

  int order() const { return Order; }
  double abs_tol() const { return abs_tol_; }
  double rel_tol() const { return rel_tol_; }

  template <Field F, PhaseState X>
  double initial_step(const BasicModel<F>& model, const X& x, double t0, double t1) {
    return core<X>().initial_step(model, x, t0, t1);
  }

  template <Field F, PhaseState X>
  bool try_step(const BasicModel<F>& model, X& x, double& t, double& dt) {
    return core<X>().try_step(model, x, t, dt);
  }

  /// The continuous extension of the last accepted step at t (between its ends).
  template <Field F>
  State dense_state(const BasicModel<F>& model, double t) {
    return plain_.dense_state(model, t);
  }
  /// The same for a run with an attitude.
  template <Field F>
  OrientedState dense_oriented_state(const BasicModel<F>& model, double t) {
    return oriented_.dense_state(model, t);
  }

  /// The largest renormalisation |‖q‖ − 1| of the attitude in one step so far.
  double attitude_projection() const { return oriented_.attitude_projection(); }

 private:
  template <class X>
  auto& core() {
    if constexpr (kOriented<X>) {
      return oriented_;
    } else {
      return plain_;
    }
  }

  double abs_tol_, rel_tol_;
  Plain plain_;
  Oriented oriented_;
};

}  // namespace detail

/// An embedded Runge–Kutta pair with odeint's standard error control:
/// err_i / (abs_tol + rel_tol (|y_i| + h |y'_i|)) ≤ 1 in the max norm. A non-finite trial is
/// rejected (odeint's controller would accept an error estimate of NaN) and retried
/// kNonFiniteShrink times shorter. After an accepted step, dense_state(model, t) is the method's
/// continuous extension inside it: Dormand–Prince's own (order 4, odeint's calc_state); for
/// Fehlberg 7(8), which has none, the Hermite interpolant of degree 7 (HermiteInterpolant) on the
/// nodes θ = 0, 1/3, 2/3, 1 of the step, the inner values from steps of θh of the same formula from
/// the step's start (built on first use: 26 more evaluations of f per interpolated step; error
/// O(h^8), the order of the pair's error estimate). A state with an attitude runs the same pair on
/// the ten numbers (dense_oriented_state for its continuous extension).
template <class ErrorStepper, int Order>
class EmbeddedRkStepper
    : public detail::AdaptivePair<
          detail::EmbeddedRkCore<ErrorStepper, Order>,
          detail::EmbeddedRkCore<detail::RebindStateT<ErrorStepper, OrientedOdeState>, Order>,
          Order> {
  using Base = detail::AdaptivePair<
      detail::EmbeddedRkCore<ErrorStepper, Order>,
      detail::EmbeddedRkCore<detail::RebindStateT<ErrorStepper, OrientedOdeState>, Order>, Order>;

 public:
  using Base::Base;
};

/// An embedded pair on the state of another model, whose odeint numbers Y (ErrorStepper's
/// state_type) OdeBinding<M, Y> binds: the same AdaptiveStepper and DenseStepper, error control
/// and continuous extension as EmbeddedRkStepper.
template <class ErrorStepper, int Order>
using EmbeddedRkOn = detail::EmbeddedRkCore<ErrorStepper, Order>;

/// Dormand–Prince 5(4) (odeint's runge_kutta_dopri5), order 5.
using Dopri5Stepper = EmbeddedRkStepper<boost::numeric::odeint::runge_kutta_dopri5<OdeState>, 5>;
/// Runge–Kutta–Fehlberg 7(8) (odeint's runge_kutta_fehlberg78): 13 stages, propagates the
/// 8th-order solution, 7th-order error estimate.
using Fehlberg78Stepper =
    EmbeddedRkStepper<boost::numeric::odeint::runge_kutta_fehlberg78<OdeState>, 8>;

/// Dense output of Dormand–Prince 5(4) (odeint's dense_output_runge_kutta): steps freely and
/// interpolates the state at any time inside the last step with the method's continuous extension.
template <Field F>
class Dopri5Dense {
 public:
  Dopri5Dense(const BasicModel<F>& model, double abs_tol, double rel_tol)
      : model_(&model),
        dense_(boost::numeric::odeint::make_dense_output(
            abs_tol, rel_tol, boost::numeric::odeint::runge_kutta_dopri5<OdeState>())) {}

  void initialize(const State& x, double t, double dt) { dense_.initialize(to_ode(x), t, dt); }
  /// One accepted step; returns (t_old, t_new).
  std::pair<double, double> do_step() { return dense_.do_step(OdeSystem<F>{model_}); }
  double current_time() const { return dense_.current_time(); }
  State current_state() const { return from_ode(dense_.current_state()); }
  /// The interpolated state at t in [t_old, t_new] of the last step.
  State calc_state(double t) const {
    OdeState y;
    dense_.calc_state(t, y);
    return from_ode(y);
  }

 private:
  const BasicModel<F>* model_;
  typename boost::numeric::odeint::result_of::make_dense_output<
      boost::numeric::odeint::runge_kutta_dopri5<OdeState>>::type dense_;
};

}  // namespace newtop
