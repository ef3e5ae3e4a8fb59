#pragma once
/// \file
/// One call that runs any method by name (method_settings.hpp: the names and their settings).

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "newtop/integrate/dop853.hpp"
#include "newtop/integrate/driver.hpp"
#include "newtop/integrate/method_settings.hpp"
#include "newtop/integrate/runge_kutta.hpp"
#include "newtop/integrate/sampled.hpp"
#include "newtop/integrate/splitting.hpp"
#include "newtop/integrate/taylor.hpp"

namespace newtop {

/// Calls fn(stepper) with a stepper of the named method (settings validated) and returns its
/// result.
template <class Fn>
decltype(auto) with_stepper(const MethodSettings& settings, Fn&& fn) {
  validate(settings);
  const MethodInfo& info = method_info(settings.name);
  if (info.kind == MethodKind::splitting) {
    const CompositionTable& table = composition_table(settings.name);
    SplittingStepper s(table, settings.ordering.value_or(default_ordering(table)));
    return fn(s);
  }
  if (info.kind == MethodKind::fixed_rk) {
    Rk4Stepper s;
    return fn(s);
  }
  if (settings.name == "dopri5") {
    Dopri5Stepper s(settings.abs_tol, settings.rel_tol);
    return fn(s);
  }
  if (settings.name == "dop853") {
    Dop853Stepper s(settings.abs_tol, settings.rel_tol);
    return fn(s);
  }
  if (settings.name == "taylor") {
    TaylorStepper s(settings.abs_tol, settings.rel_tol);
    return fn(s);
  }
  Fehlberg78Stepper s(settings.abs_tol, settings.rel_tol);
  return fn(s);
}

/// Runs the named method from (t0, x) to t1 with the driver.
template <Field F, class Obs = NoObserver, PhaseState X = State>
Outcome run_method(const MethodSettings& settings, const BasicModel<F>& model, const X& x,
                   double t0, double t1, IntegrateOptions options = {}, Obs&& observer = {}) {
  options.step = settings.step;
  return with_stepper(settings,
                      [&](auto& s) { return integrate(s, model, x, t0, t1, options, observer); });
}

/// Runs the named method from (t0, x) to t1 and reports the state at the output times to
/// sample(k, t_k, state) (integrate_sampled: dense output of the adaptive methods; fixed-step
/// methods land on every output time).
template <Field F, class Sample, class Obs = NoObserver, PhaseState X = State>
Outcome run_method_sampled(const MethodSettings& settings, const BasicModel<F>& model, const X& x,
                           double t0, double t1, const OutputTimes& times, IntegrateOptions options,
                           Sample&& sample, Obs&& observer = {}) {
  options.step = settings.step;
  return with_stepper(settings, [&](auto& s) {
    return integrate_sampled(s, model, x, t0, t1, times, options, sample, observer);
  });
}

}  // namespace newtop
