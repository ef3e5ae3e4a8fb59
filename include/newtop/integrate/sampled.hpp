#pragma once
/// \file
/// Output at the times a user asks for (output_times.hpp): a driver on top of integrate().
/// Adaptive methods read the state at each output time from the continuous extension of the
/// accepted step that contains it (an observer of DenseSteps); fixed-step methods land on every
/// output time.

#include <cstdint>

#include "newtop/integrate/driver.hpp"
#include "newtop/integrate/output_times.hpp"

namespace newtop {

namespace detail {

/// The observer that samples the continuous extension of each accepted step at the output times it
/// contains, then passes the step on to `inner`.
template <class Sample, class Obs>
struct SamplingObserver {
  const OutputTimes& times;
  Sample& sample;
  Obs& inner;
  double dir;
  std::int64_t next = 0;

  template <class X, class Step>
  void operator()(double t, const X& x, const Step& step) {
    for (; next < times.size() && dir * (times[next] - t) <= 0; ++next) {
      const double tk = times[next];
      sample(next, tk, tk == t ? x : step.state(tk));
    }
    notify(inner, t, x, step);
  }
};

/// The sampled run on any model M and state X (the two integrate_sampled below).
template <class S, class M, class X, class Sample, class Obs>
OutcomeOf<X> run_sampled(S& stepper, const M& model, X x, double t0, double t1,
                         const OutputTimes& times, const IntegrateOptions& opt, Sample& sample,
                         Obs& observer) {
  const double dir = t1 < t0 ? -1.0 : 1.0;
  if constexpr (AdaptiveStepper<S, M, X>) {
    SamplingObserver<Sample, Obs> obs{times, sample, observer, dir};
    return run_adaptive(stepper, model, x, t0, t1, opt, obs);
  } else {
    check_options(opt);
    check_state(x);
    fixed_step_count(t0, t1, opt.step);  // checks the times and the step
    OutcomeOf<X> out = start_outcome(t0, x);
    observer(t0, x);
    double a = t0;
    for (std::int64_t k = 0; k <= times.size(); ++k) {
      const double b = k < times.size() ? times[k] : t1;
      if (b != a) {
        const std::int64_t n = fixed_step_count(a, b, opt.step);
        const bool go_on = fixed_steps(stepper, model, x, a, b, n, opt, out, observer);
        record_projection(out, stepper);
        if (!go_on) return out;
        a = b;
      }
      if (k < times.size()) sample(k, b, x);
    }
    return out;
  }
}

}  // namespace detail

/// Runs from t0 to t1 as integrate() does and reports the state at every output time, in order, to
/// sample(k, t_k, state). Adaptive methods: the method's continuous extension inside the accepted
/// step that contains t_k (dense_output.hpp). Fixed-step methods land on every output time: each
/// interval between consecutive output times, and the last one to t1, is split into
/// n = ceil(length / h) equal steps, so that OutputTimes::every(D) runs at the step D / ceil(D / h)
/// (≤ h, dividing D). `observer` sees every accepted step. Output times after the point where a
/// run stopped (outcome other than finished) are not sampled.
template <class S, Field F, class Sample, class Obs = NoObserver, PhaseState X = State>
Outcome integrate_sampled(S& stepper, const BasicModel<F>& model, X x, double t0, double t1,
                          const OutputTimes& times, const IntegrateOptions& opt, Sample&& sample,
                          Obs&& observer = {}) {
  return detail::run_sampled(stepper, model, x, t0, t1, times, opt, sample, observer);
}

/// The same on a model with a state of its own (ModelWithState).
template <class S, ModelWithState M, class Sample, class Obs = NoObserver>
OutcomeOf<typename M::state_type> integrate_sampled(S& stepper, const M& model,
                                                    typename M::state_type x, double t0, double t1,
                                                    const OutputTimes& times,
                                                    const IntegrateOptions& opt, Sample&& sample,
                                                    Obs&& observer = {}) {
  return detail::run_sampled(stepper, model, x, t0, t1, times, opt, sample, observer);
}

}  // namespace newtop
