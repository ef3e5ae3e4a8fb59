#pragma once
/// \file
/// The tangent runs (fixed-step and adaptive) and the chaos indicators on a BasicModel<F>
/// (templates; chaos.hpp declares them on a Model, compiled once in the library).

#include <cmath>
#include <cstdint>
#include <functional>
#include <type_traits>

#include "newtop/phase/chaos.hpp"
#include "newtop/phase/one_step.hpp"
#include "newtop/phase/tangent_of.hpp"

namespace newtop::phase {

/// n equal steps of a tangent stepper from (t0, x, V) to t1 (n = fixed_step_count(t0, t1, h)),
/// observer(t, x, V) after each; stops at a non-finite state or tangent.
template <class S, Field F, class Obs>
Outcome integrate_tangent(S& stepper, const BasicModel<F>& model, State x, Tangent V, double t0,
                          double t1, const IntegrateOptions& opt, Obs&& observer) {
  check_options(opt);
  check_state(x);
  const std::int64_t n = fixed_step_count(t0, t1, opt.step);
  Outcome out{Status::finished, t0, x, 0, 0, 0.0};
  const double h = n > 0 ? (t1 - t0) / static_cast<double>(n) : 0.0;
  for (std::int64_t i = 1; i <= n; ++i) {
    if (out.steps >= opt.max_steps) {
      out.status = Status::step_limit;
      return out;
    }
    stepper.step(model, x, V, h);
    const double t = (i == n) ? t1 : t0 + static_cast<double>(i) * h;
    if (!is_finite(x) || !V.allFinite()) {
      out.status = Status::non_finite;
      return out;
    }
    out.t = t;
    out.state = x;
    ++out.steps;
    out.last_step = h;
    observer(t, x, V);
  }
  return out;
}

/// The same with an adaptive tangent stepper: accepted steps from t0 to t1 (the last one shortened
/// to land on t1), rejected trials retried with the suggested step, observer after each accepted
/// step; a step below opt.min_step_factor times the span is an underflow.
template <class S, Field F, class Obs>
requires requires(S s, const BasicModel<F>& m, State& x, Tangent& V, double& t) {
  s.try_step(m, x, V, t, t);
}
Outcome integrate_tangent_adaptive(S& stepper, const BasicModel<F>& model, State x, Tangent V,
                                   double t0, double t1, const IntegrateOptions& opt,
                                   Obs&& observer) {
  check_time_span(t0, t1);
  check_options(opt);
  check_state(x);
  Outcome out{Status::finished, t0, x, 0, 0, 0.0};
  const double span = t1 - t0;
  if (span == 0.0) return out;
  const double dir = span > 0 ? 1.0 : -1.0;
  double dt =
      dir * (opt.initial_step > 0 ? opt.initial_step : stepper.initial_step(model, x, t0, t1));
  double t = t0;
  while (dir * (t1 - t) > 0) {
    if (out.steps + out.rejected >= opt.max_steps) {
      out.status = Status::step_limit;
      return out;
    }
    bool last = false;
    if (dir * (t + dt - t1) >= 0) {
      dt = t1 - t;
      last = true;
    }
    if (!(std::abs(dt) >= opt.min_step_factor * std::max(std::abs(t), std::abs(span)))) {
      out.status = Status::step_size_underflow;
      return out;
    }
    State xt = x;
    Tangent Vt = V;
    double tt = t;
    const double tried = dt;
    if (!stepper.try_step(model, xt, Vt, tt, dt) || !is_finite(xt) || !Vt.allFinite()) {
      if (!is_finite(xt) || !Vt.allFinite() || !std::isfinite(dt)) dt = kNonFiniteShrink * tried;
      ++out.rejected;
      continue;
    }
    x = xt;
    V = Vt;
    t = last ? t1 : tt;
    ++out.steps;
    out.t = t;
    out.state = x;
    out.last_step = tried;
    observer(t, x, V);
  }
  return out;
}

/// The indicators of the orbit from (t0, x0) to t1 with the named method; `history`
/// receives a sample every `every` steps (and the last), `on_step(t)` is called after each step.
template <Field F>
ChaosResult chaos_run(const MethodSettings& method, const BasicModel<F>& model, const State& x0,
                      double t0, double t1, IntegrateOptions options, bool spectrum,
                      const std::function<void(const ChaosSample&)>& history = {},
                      std::int64_t every = 1, const std::function<void(double)>& on_step = {}) {
  options.step = method.step;
  const int vectors = spectrum ? 6 : 1;
  check_tangent_method(method);
  return with_tangent_stepper(method, [&](auto& s) {
    ChaosIndicators ind(t0, vectors);
    std::int64_t count = 0;
    auto obs = [&](double t, const State&, Tangent& V) {
      if (on_step) on_step(t);
      ind(t, V);
      if (history && ++count % every == 0) history(ind.sample());
    };
    ChaosResult r;
    using S = std::decay_t<decltype(s)>;
    if constexpr (requires(S & st, State & x, Tangent & V, double& t) {
                    st.try_step(model, x, V, t, t);
                  }) {
      r.outcome =
          integrate_tangent_adaptive(s, model, x0, initial_tangent(vectors), t0, t1, options, obs);
    } else {
      r.outcome = integrate_tangent(s, model, x0, initial_tangent(vectors), t0, t1, options, obs);
    }
    r.indicators = ind.sample();
    if (history && count % every != 0) history(r.indicators);
    return r;
  });
}

/// Benettin's two-trajectory estimate of λ_max: a companion started at distance d0 along
/// initial_tangent(1) (in the max norm of the state), both advanced by the plain stepper of the
/// method, the companion pulled back to distance d0 every `renorm` steps; Σ ln(d/d0)/(t − t0).
template <Field F>
double two_trajectory_lyapunov(const MethodSettings& method, const BasicModel<F>& model,
                               const State& x0, double t0, double t1, double d0 = 1e-8,
                               int renorm = 10) {
  const std::int64_t n = fixed_step_count(t0, t1, method.step);
  const double h = (t1 - t0) / static_cast<double>(n);
  return with_stepper(method, [&](auto& s) {
    using S = std::decay_t<decltype(s)>;
    OneStepMap<S> map1(s), map2(s);
    const Tangent v = initial_tangent(1);
    auto sub = [](const State& a, const State& b) {
      Eigen::Matrix<double, 6, 1> d;
      d << a.m - b.m, a.gamma - b.gamma;
      return d;
    };
    State x = x0, y{x0.m + d0 * v.col(0).head<3>(), x0.gamma + d0 * v.col(0).tail<3>()};
    double sum = 0;
    for (std::int64_t i = 1; i <= n; ++i) {
      x = map1(model, x, h);
      y = map2(model, y, h);
      if (i % renorm == 0 || i == n) {
        const Eigen::Matrix<double, 6, 1> d = sub(y, x);
        const double dn = d.norm();
        sum += std::log(dn / d0);
        const Eigen::Matrix<double, 6, 1> e = (d0 / dn) * d;
        y = {x.m + e.head<3>(), x.gamma + e.tail<3>()};
      }
    }
    return sum / (t1 - t0);
  });
}

}  // namespace newtop::phase
