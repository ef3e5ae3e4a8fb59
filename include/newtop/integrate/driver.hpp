#pragma once
/// \file
/// The one driver: integrate(stepper, model, state, t0, t1, options, observer) -> Outcome.
/// Observers record; they are called at t0 and after every accepted step with (t, state).

#include <cmath>
#include <cstdint>
#include <limits>

#include "newtop/integrate/concepts.hpp"
#include "newtop/integrate/outcome.hpp"

namespace newtop {

struct IntegrateOptions {
  /// Fixed-step methods: the nominal step h > 0. The run takes n = ceil((t1 − t0)/h) equal steps
  /// of (t1 − t0)/n, so that it ends exactly at t1; t_n = t0 + n h is computed, never accumulated.
  double step = 0.0;
  /// Adaptive methods: first trial step (0: |t1 − t0| / 1000).
  double initial_step = 0.0;
  /// Adaptive methods: a trial or accepted step below min_step_factor · max(|t|, |t1 − t0|) is an
  /// underflow: finishing would take over 1e12 steps, or the tolerance is below what round-off
  /// allows (the error estimate then vanishes at tiny steps and the run would creep on forever).
  double min_step_factor = 1e-12;
  /// Both: at most this many accepted steps (adaptive: also counts rejected trials).
  std::int64_t max_steps = 1'000'000'000;
};

/// An observer that records nothing.
struct NoObserver {
  void operator()(double, const State&) const {}
};

inline bool is_finite(const State& s) { return s.m.allFinite() && s.gamma.allFinite(); }

/// Fixed-step driver.
template <class S, Field F, class Obs = NoObserver>
requires FixedStepper<S, BasicModel<F>> Outcome integrate(S& stepper, const BasicModel<F>& model,
                                                          State x, double t0, double t1,
                                                          const IntegrateOptions& opt,
                                                          Obs&& observer = {}) {
  Outcome out{Status::finished, t0, x, 0, 0, 0.0};
  observer(t0, x);
  const double span = t1 - t0;
  if (span == 0.0) return out;
  const double n_real = std::ceil(std::abs(span) / opt.step);
  const auto n = static_cast<std::int64_t>(n_real);
  const double h = span / n_real;
  for (std::int64_t i = 1; i <= n; ++i) {
    if (out.steps >= opt.max_steps) {
      out.status = Status::step_limit;
      return out;
    }
    stepper.step(model, x, h);
    if (!is_finite(x)) {
      out.status = Status::non_finite;
      out.t = t0 + static_cast<double>(i) * h;
      return out;
    }
    const double t = (i == n) ? t1 : t0 + static_cast<double>(i) * h;
    out.t = t;
    out.state = x;
    out.steps = i;
    out.last_step = h;
    observer(t, x);
  }
  return out;
}

/// Adaptive driver: the last step is shortened to land exactly on t1.
template <class S, Field F, class Obs = NoObserver>
requires AdaptiveStepper<S, BasicModel<F>> Outcome integrate(S& stepper, const BasicModel<F>& model,
                                                             State x, double t0, double t1,
                                                             const IntegrateOptions& opt,
                                                             Obs&& observer = {}) {
  Outcome out{Status::finished, t0, x, 0, 0, 0.0};
  observer(t0, x);
  const double span = t1 - t0;
  if (span == 0.0) return out;
  const double dir = span > 0 ? 1.0 : -1.0;
  double dt = opt.initial_step > 0 ? dir * opt.initial_step : span / 1000.0;
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
    const double scale = std::max(std::abs(t), std::abs(span));
    if (std::abs(dt) < opt.min_step_factor * scale) {
      out.status = Status::step_size_underflow;
      return out;
    }
    State trial = x;
    double t_trial = t;
    const double dt_tried = dt;
    if (!stepper.try_step(model, trial, t_trial, dt)) {
      ++out.rejected;
      continue;
    }
    if (!is_finite(trial)) {
      out.status = Status::non_finite;
      out.t = t_trial;
      return out;
    }
    if (std::abs(dt_tried) < opt.min_step_factor * scale) {
      out.status = Status::step_size_underflow;
      return out;
    }
    x = trial;
    t = last ? t1 : t_trial;
    ++out.steps;
    out.t = t;
    out.state = x;
    out.last_step = dt_tried;
    observer(t, x);
  }
  return out;
}

}  // namespace newtop
