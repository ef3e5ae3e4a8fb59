#pragma once
/// \file
/// The one driver: integrate(stepper, model, state, t0, t1, options, observer) -> Outcome.
/// Observers record; they are called at t0 and after every accepted step with (t, state). An
/// observer that also takes a third argument receives, with adaptive methods, the accepted step's
/// continuous extension (a DenseStep, dense_output.hpp): output at requested times and event
/// location are observers of that kind (output_times.hpp), not stepper features.
///
/// The state is a State (m, γ), or an OrientedState that also carries the attitude q (body →
/// inertial): the same driver, compiled separately for each, so a run without an attitude pays
/// nothing for it. The Outcome then holds the final attitude and the largest renormalisation of q
/// in one step.

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "newtop/integrate/concepts.hpp"
#include "newtop/integrate/dense_output.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/integrate/outcome.hpp"

namespace newtop {

/// An observer that records nothing.
struct NoObserver {
  template <class X>
  void operator()(double, const X&) const {}
};

/// The Outcome type of a run on states X: Outcome for State and OrientedState; a model with a
/// state of its own specialises it (its outcome has at least status, t, state, steps, rejected and
/// last_step).
template <class X>
struct OutcomeFor {
  using type = Outcome;
};
template <class X>
using OutcomeOf = typename OutcomeFor<X>::type;

/// A model that names its own state type (M::state_type): a model other than BasicModel<F> that
/// runs through the same driver, with check_state(x) and is_finite(x) for its state and
/// OutcomeFor specialised (the engine knows nothing else of it).
template <class M>
concept ModelWithState = requires {
  typename M::state_type;
};

namespace detail {

/// The outcome of a run that has not moved from (t0, x).
template <class X>
OutcomeOf<X> start_outcome(double t0, const X& x) {
  OutcomeOf<X> out;
  out.t = t0;
  out.state = x;
  if constexpr (kOriented<X>) out.attitude = x.q;
  return out;
}

/// Records the accepted state x in `out`.
template <class X, class Out>
void record(Out& out, const X& x) {
  out.state = x;
  if constexpr (kOriented<X>) out.attitude = x.q;
}

/// One fixed step of h from (t, x): step(model, x, t, h) for a stepper of a non-autonomous model
/// (one that needs the independent variable at the start of the step), step(model, x, h)
/// otherwise.
template <class S, class M, class X>
void advance(S& stepper, const M& model, X& x, double t, double h) {
  if constexpr (requires { stepper.step(model, x, t, h); }) {
    stepper.step(model, x, t, h);
  } else {
    stepper.step(model, x, h);
  }
}

/// The stepper's largest renormalisation of the attitude, into `out`.
template <class S, class Out>
void record_projection(Out& out, const S& stepper) {
  if constexpr (requires { out.attitude_projection = stepper.attitude_projection(); }) {
    out.attitude_projection = stepper.attitude_projection();
  }
}

/// Calls observer(t, x, step) when the observer takes the step, observer(t, x) otherwise.
template <class Obs, class X, class Step>
void notify(Obs& observer, double t, const X& x, const Step& step) {
  if constexpr (std::is_invocable_v<Obs&, double, const X&, const Step&>) {
    observer(t, x, step);
  } else {
    observer(t, x);
  }
}

/// n equal steps from (t0, x) to t1 (the last one lands exactly on t1), continuing the counts in
/// `out`. Returns false when the run stopped (non-finite state or step limit; `out` says which).
template <class S, class M, class X, class Out, class Obs>
bool fixed_steps(S& stepper, const M& model, X& x, double t0, double t1, std::int64_t n,
                 const IntegrateOptions& opt, Out& out, Obs& observer) {
  const double h = (t1 - t0) / static_cast<double>(n);
  for (std::int64_t i = 1; i <= n; ++i) {
    if (out.steps >= opt.max_steps) {
      out.status = Status::step_limit;
      return false;
    }
    advance(stepper, model, x, t0 + static_cast<double>(i - 1) * h, h);
    const double t = (i == n) ? t1 : t0 + static_cast<double>(i) * h;
    if (!is_finite(x)) {
      out.status = Status::non_finite;  // out keeps the last finite state and its time
      return false;
    }
    out.t = t;
    record(out, x);
    ++out.steps;
    out.last_step = h;
    observer(t, x);
  }
  return true;
}

}  // namespace detail

namespace detail {

/// The fixed-step run of integrate() on any model M and state X.
template <class S, class M, class X, class Obs>
OutcomeOf<X> run_fixed(S& stepper, const M& model, X x, double t0, double t1,
                       const IntegrateOptions& opt, Obs& observer) {
  check_options(opt);
  check_state(x);
  const std::int64_t n = fixed_step_count(t0, t1, opt.step);
  OutcomeOf<X> out = start_outcome(t0, x);
  observer(t0, x);
  if (n > 0) fixed_steps(stepper, model, x, t0, t1, n, opt, out, observer);
  record_projection(out, stepper);
  return out;
}

/// The adaptive run of integrate() on any model M and state X: the one adaptive driver loop.
template <class S, class M, class X, class Obs>
OutcomeOf<X> run_adaptive(S& stepper, const M& model, X x, double t0, double t1,
                          const IntegrateOptions& opt, Obs& observer) {
  using Step = DenseStep<S, M, X>;
  check_time_span(t0, t1);
  check_options(opt);
  check_state(x);
  OutcomeOf<X> out = start_outcome(t0, x);
  notify(observer, t0, x, Step{stepper, model, t0, t0, x});
  const double span = t1 - t0;
  if (span == 0.0) return out;
  const double dir = span > 0 ? 1.0 : -1.0;
  double dt =
      dir * (opt.initial_step > 0 ? opt.initial_step : stepper.initial_step(model, x, t0, t1));
  double t = t0;
  while (dir * (t1 - t) > 0) {
    if (out.steps + out.rejected >= opt.max_steps) {
      out.status = Status::step_limit;
      record_projection(out, stepper);
      return out;
    }
    bool last = false;
    if (dir * (t + dt - t1) >= 0) {
      dt = t1 - t;
      last = true;
    }
    const double scale = std::max(std::abs(t), std::abs(span));
    if (!(std::abs(dt) >= opt.min_step_factor * scale)) {
      out.status = Status::step_size_underflow;
      record_projection(out, stepper);
      return out;
    }
    X trial = x;
    double t_trial = t;
    const double dt_tried = dt;
    const bool accepted = stepper.try_step(model, trial, t_trial, dt);
    // A non-finite trial is a rejected step, retried shorter, whatever the stepper said (an error
    // estimate of NaN passes a controller that tests err > 1).
    const bool non_finite = accepted && !is_finite(trial);
    if (!accepted || non_finite) {
      if (non_finite || !std::isfinite(dt)) dt = kNonFiniteShrink * dt_tried;
      ++out.rejected;
      continue;
    }
    const double t_old = t;
    x = trial;
    t = last ? t1 : t_trial;
    ++out.steps;
    out.t = t;
    record(out, x);
    out.last_step = dt_tried;
    notify(observer, t, x, Step{stepper, model, t_old, t, x});
  }
  record_projection(out, stepper);
  return out;
}

}  // namespace detail

/// Fixed-step driver. Throws InputError for non-finite times or state, a step that is not a finite
/// number > 0, or a step count beyond kMaxStepCount.
template <class S, Field F, class Obs = NoObserver, PhaseState X = State>
requires FixedStepper<S, BasicModel<F>, X> Outcome integrate(S& stepper, const BasicModel<F>& model,
                                                             X x, double t0, double t1,
                                                             const IntegrateOptions& opt,
                                                             Obs&& observer = {}) {
  return detail::run_fixed(stepper, model, x, t0, t1, opt, observer);
}

/// Adaptive driver: the first trial step is the stepper's estimate from the problem (or
/// opt.initial_step), a trial that gives NaN or inf is rejected and retried kNonFiniteShrink times
/// shorter (only an accepted state counts; a run whose trials keep failing ends in
/// step_size_underflow), and the last step is shortened to land exactly on t1. Throws InputError as
/// the fixed-step driver does for bad times, state or options.
template <class S, Field F, class Obs = NoObserver, PhaseState X = State>
requires AdaptiveStepper<S, BasicModel<F>, X> Outcome integrate(S& stepper,
                                                                const BasicModel<F>& model, X x,
                                                                double t0, double t1,
                                                                const IntegrateOptions& opt,
                                                                Obs&& observer = {}) {
  return detail::run_adaptive(stepper, model, x, t0, t1, opt, observer);
}

/// The same drivers on a model with a state of its own (ModelWithState): the same loops.
template <class S, ModelWithState M, class Obs = NoObserver>
requires FixedStepper<S, M, typename M::state_type> OutcomeOf<typename M::state_type> integrate(
    S& stepper, const M& model, typename M::state_type x, double t0, double t1,
    const IntegrateOptions& opt, Obs&& observer = {}) {
  return detail::run_fixed(stepper, model, x, t0, t1, opt, observer);
}
template <class S, ModelWithState M, class Obs = NoObserver>
requires AdaptiveStepper<S, M, typename M::state_type> OutcomeOf<typename M::state_type> integrate(
    S& stepper, const M& model, typename M::state_type x, double t0, double t1,
    const IntegrateOptions& opt, Obs&& observer = {}) {
  return detail::run_adaptive(stepper, model, x, t0, t1, opt, observer);
}

}  // namespace newtop
