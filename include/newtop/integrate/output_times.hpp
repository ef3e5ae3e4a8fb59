#pragma once
/// \file
/// Output at the times a user asks for: t0 + k·D, or a list. A driver on top of integrate():
/// adaptive methods read the state at each output time from the continuous extension of the
/// accepted step that contains it (an observer of DenseSteps); fixed-step methods land on every
/// output time.

#include <cstdint>
#include <vector>

#include "newtop/integrate/driver.hpp"

namespace newtop {

/// The times at which a run reports its state, in the direction of the run.
class OutputTimes {
 public:
  /// t0 + k·D·sign(t1 − t0) for k = 0, 1, …, n, every such time up to t1. Each is one product and
  /// one sum, never accumulated. When t0 + (n + 1)·D lies past t1 by no more than 4 ulp of t1 (a
  /// rounding of a time meant to be t1, as 3 · 0.1 = 0.30000000000000004 for t1 = 0.3), the last
  /// time is t1 itself. Throws InputError for D not a finite number > 0, non-finite times, or more
  /// than kMaxStepCount times.
  static OutputTimes every(double D, double t0, double t1);
  /// The given times: finite, inside [t0, t1] (or [t1, t0]) and strictly ordered in the run's
  /// direction; throws InputError naming the first one that is not.
  static OutputTimes list(std::vector<double> times, double t0, double t1);

  std::int64_t size() const { return n_; }
  double operator[](std::int64_t k) const;
  /// D for OutputTimes::every, 0 for a list.
  double interval() const { return D_; }

 private:
  double t0_ = 0, t1_ = 0, D_ = 0, dir_ = 1;
  std::int64_t n_ = 0;
  bool last_is_t1_ = false;
  std::vector<double> list_;
};

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
  const double dir = t1 < t0 ? -1.0 : 1.0;
  if constexpr (AdaptiveStepper<S, BasicModel<F>, X>) {
    detail::SamplingObserver<Sample, Obs> obs{times, sample, observer, dir};
    return integrate(stepper, model, x, t0, t1, opt, obs);
  } else {
    check_options(opt);
    check_state(x);
    fixed_step_count(t0, t1, opt.step);  // checks the times and the step
    Outcome out = detail::start_outcome(t0, x);
    observer(t0, x);
    double a = t0;
    for (std::int64_t k = 0; k <= times.size(); ++k) {
      const double b = k < times.size() ? times[k] : t1;
      if (b != a) {
        const std::int64_t n = fixed_step_count(a, b, opt.step);
        const bool go_on = detail::fixed_steps(stepper, model, x, a, b, n, opt, out, observer);
        detail::record_projection(out, stepper);
        if (!go_on) return out;
        a = b;
      }
      if (k < times.size()) sample(k, b, x);
    }
    return out;
  }
}

}  // namespace newtop
