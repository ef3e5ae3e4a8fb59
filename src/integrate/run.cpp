#include "newtop/integrate/run.hpp"

#include "newtop/exact/model_fields.hpp"
#include "newtop/integrate/methods.hpp"
#include "newtop/model/state_checks.hpp"

namespace newtop {
namespace {

/// The one instantiation of every method, field and state type. The observer is tested once per
/// step (a branch against a step's field evaluations) rather than compiled twice, with and without.
template <class X>
Outcome run_any(const MethodSettings& method, const Model& model, const X& x, double t0, double t1,
                const IntegrateOptions& options, const StepObserver<X>& observer) {
  return visit_model(model, [&](const auto& m) {
    return run_method(method, m, x, t0, t1, options, [&observer](double t, const X& s) {
      if (observer) observer(t, s);
    });
  });
}

template <class X>
Outcome run_any_sampled(const MethodSettings& method, const Model& model, const X& x, double t0,
                        double t1, const OutputTimes& times, const IntegrateOptions& options,
                        const SampleObserver<X>& sample, const StepObserver<X>& observer) {
  auto on_sample = [&sample](std::int64_t k, double t, const X& s) {
    if (sample) sample(k, t, s);
  };
  return visit_model(model, [&](const auto& m) {
    return run_method_sampled(method, m, x, t0, t1, times, options, on_sample,
                              [&observer](double t, const X& s) {
                                if (observer) observer(t, s);
                              });
  });
}

}  // namespace

Outcome run_method(const MethodSettings& method, const Model& model, const State& x, double t0,
                   double t1, IntegrateOptions options, const StepObserver<State>& observer) {
  validate(static_cast<const State&>(x));
  return run_any(method, model, x, t0, t1, options, observer);
}

Outcome run_method(const MethodSettings& method, const Model& model, const OrientedState& x,
                   double t0, double t1, IntegrateOptions options,
                   const StepObserver<OrientedState>& observer) {
  validate(static_cast<const State&>(x));
  return run_any(method, model, x, t0, t1, options, observer);
}

Outcome run_method_sampled(const MethodSettings& method, const Model& model, const State& x,
                           double t0, double t1, const OutputTimes& times, IntegrateOptions options,
                           const SampleObserver<State>& sample,
                           const StepObserver<State>& observer) {
  validate(static_cast<const State&>(x));
  return run_any_sampled(method, model, x, t0, t1, times, options, sample, observer);
}

Outcome run_method_sampled(const MethodSettings& method, const Model& model, const OrientedState& x,
                           double t0, double t1, const OutputTimes& times, IntegrateOptions options,
                           const SampleObserver<OrientedState>& sample,
                           const StepObserver<OrientedState>& observer) {
  validate(static_cast<const State&>(x));
  return run_any_sampled(method, model, x, t0, t1, times, options, sample, observer);
}

}  // namespace newtop
