#pragma once
/// \file
/// Methods by name, for scenario files and the command line, and one call that runs any of them.

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "newtop/integrate/driver.hpp"
#include "newtop/integrate/output_times.hpp"
#include "newtop/integrate/runge_kutta.hpp"
#include "newtop/integrate/splitting.hpp"

namespace newtop {

enum class MethodKind { splitting, fixed_rk, adaptive };

struct MethodInfo {
  std::string_view name;
  MethodKind kind;
  int order;
  std::string_view description;
};

/// Every method newtop can run: the splitting compositions, rk4, dopri5, rkf78.
std::span<const MethodInfo> methods();
/// The method with this name; throws InputError listing the known names if there is none.
const MethodInfo& method_info(std::string_view name);

/// Default method when only a step is given: the splitting method with the best work–precision
/// at moderate accuracy (docs/performance.md).
inline constexpr std::string_view kDefaultFixedMethod = "splitting6";
/// Default method when only a tolerance is given.
inline constexpr std::string_view kDefaultAdaptiveMethod = "rkf78";

/// What to run: a method by name with its step (fixed-step methods) or tolerances (adaptive).
struct MethodSettings {
  std::string name{kDefaultFixedMethod};
  double step = 0.0;
  double abs_tol = 1e-12;
  double rel_tol = 1e-12;
  /// Splitting methods: the ordering of the split; default_ordering(table) when absent.
  std::optional<SplitOrdering> ordering;
};

/// Checks the settings (known name, a step > 0 for fixed-step methods, tolerances > 0 for adaptive
/// ones); throws InputError naming the field.
void validate(const MethodSettings& settings);

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
