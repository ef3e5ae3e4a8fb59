// Orbit integrators by name, for scenario files and the command line: the orbit's splitting
// stepper and the engine's embedded Runge–Kutta pairs on the orbit state, every run through the
// engine's driver (integrate/driver.hpp) and sampled output (integrate/sampled.hpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "newtop/integrate/dop853.hpp"
#include "newtop/integrate/runge_kutta.hpp"
#include "newtop/integrate/sampled.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "newtop/orbit/orbit_taylor.hpp"

namespace newtop {

/// The orbit state as odeint sees it: (m, γ, n), nine numbers.
using OrbitOdeState = std::array<double, 9>;

namespace {

OrbitOdeState to_orbit_ode(const OrbitState& s) {
  return {s.m[0],     s.m[1],      s.m[2],      s.gamma[0], s.gamma[1],
          s.gamma[2], s.normal[0], s.normal[1], s.normal[2]};
}

OrbitState from_orbit_ode(const OrbitOdeState& y) {
  return {Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5]), Vec3(y[6], y[7], y[8])};
}

/// The vector field of an orbit model in odeint's convention (t: the time, or ν on an ellipse).
template <class M>
struct OrbitOdeSystem {
  const M* model;
  void operator()(const OrbitOdeState& y, OrbitOdeState& dydt, double t) const {
    if constexpr (std::is_same_v<M, EllipticOrbitModel>) {
      dydt = to_orbit_ode(rhs(*model, from_orbit_ode(y), t));
    } else {
      dydt = to_orbit_ode(rhs(*model, from_orbit_ode(y)));
    }
  }
};

}  // namespace

/// The orbit models on odeint's numbers: what the engine's embedded pairs need of them.
template <class O>
struct OdeBinding<BasicOrbitModel<O>, OrbitOdeState> {
  using state_type = OrbitState;
  using system = OrbitOdeSystem<BasicOrbitModel<O>>;
  static OrbitOdeState to(const OrbitState& x) { return to_orbit_ode(x); }
  static OrbitState from(const OrbitOdeState& y) { return from_orbit_ode(y); }
};

namespace {

namespace odeint = boost::numeric::odeint;
using OrbitRkf78 = EmbeddedRkOn<odeint::runge_kutta_fehlberg78<OrbitOdeState>, 8>;
using OrbitDopri5 = EmbeddedRkOn<odeint::runge_kutta_dopri5<OrbitOdeState>, 5>;
using OrbitDop853 = Dop853On<OrbitOdeState>;

constexpr std::array<std::string_view, 4> kAdaptive{"rkf78", "dopri5", "dop853", "taylor"};

/// Calls fn(stepper) with a stepper of the named method (settings validated).
template <class Fn>
decltype(auto) with_orbit_stepper(const MethodSettings& settings, Fn&& fn) {
  validate_orbit_method(settings);
  if (settings.name == "rkf78") {
    OrbitRkf78 s(settings.abs_tol, settings.rel_tol);
    return fn(s);
  }
  if (settings.name == "dopri5") {
    OrbitDopri5 s(settings.abs_tol, settings.rel_tol);
    return fn(s);
  }
  if (settings.name == "dop853") {
    OrbitDop853 s(settings.abs_tol, settings.rel_tol);
    return fn(s);
  }
  if (settings.name == "taylor") {
    OrbitTaylorStepper s(settings.abs_tol, settings.rel_tol);
    return fn(s);
  }
  const OrbitSplittingStepper s(composition_table(settings.name));
  return fn(s);
}

/// The driver's options of a run from a to b: the adaptive methods' first trial step is
/// |b − a|/1000 on an orbit (the orbit's runs have always started so; the step controller takes
/// over after one trial).
IntegrateOptions run_options(const MethodSettings& settings, std::int64_t max_steps, double a,
                             double b) {
  IntegrateOptions o;
  o.step = settings.step;
  o.max_steps = max_steps;
  if (is_orbit_adaptive_method(settings.name)) o.initial_step = std::abs(b - a) / 1000.0;
  return o;
}

template <class M>
OrbitOutcome run(const MethodSettings& settings, const M& model, const OrbitState& x, double a,
                 double b, std::int64_t max_steps, const OrbitObserver& observer) {
  const IntegrateOptions o = run_options(settings, max_steps, a, b);
  return with_orbit_stepper(settings, [&](auto& s) {
    if (!observer) return integrate(s, model, x, a, b, o);
    return integrate(s, model, x, a, b, o, observer);
  });
}

template <class M>
OrbitOutcome run_sampled(const MethodSettings& settings, const M& model, const OrbitState& x,
                         double a, double b, const OutputTimes& times, std::int64_t max_steps,
                         const OrbitSample& sample, const OrbitObserver& observer) {
  const IntegrateOptions o = run_options(settings, max_steps, a, b);
  auto on_sample = [&sample](std::int64_t k, double t, const OrbitState& s) {
    if (sample) sample(k, t, s);
  };
  return with_orbit_stepper(settings, [&](auto& s) {
    if (!observer) return integrate_sampled(s, model, x, a, b, times, o, on_sample);
    return integrate_sampled(s, model, x, a, b, times, o, on_sample, observer);
  });
}

template <class M>
OrbitOutcome run_adaptive(const M& model, const OrbitState& x, double a, double b,
                          const OrbitAdaptiveOptions& opt, const OrbitObserver& observer) {
  OrbitRkf78 s(opt.abs_tol, opt.rel_tol);
  IntegrateOptions o;
  o.initial_step = opt.initial_step > 0 ? opt.initial_step : std::abs(b - a) / 1000.0;
  o.min_step_factor = opt.min_step_factor;
  o.max_steps = opt.max_steps;
  if (!observer) return integrate(s, model, x, a, b, o);
  return integrate(s, model, x, a, b, o, observer);
}

/// One step of the named method's propagated formula, without error control (Taylor's: the
/// series through x at the order of its tolerances).
template <class M>
OrbitState one_step(const MethodSettings& method, const M& model, const OrbitState& x, double t,
                    double h) {
  const std::string& name = method.name;
  if (name == "taylor") {
    return OrbitTaylorStepper(method.abs_tol, method.rel_tol).formula_step(model, x, t, h);
  }
  if (name == "dop853") {
    // The tolerances play no part in the formula.
    return OrbitDop853(1.0, 1.0).formula_step(model, x, t, h);
  }
  OrbitOdeState y = to_orbit_ode(x);
  const OrbitOdeSystem<M> sys{&model};
  if (name == "dopri5") {
    odeint::runge_kutta_dopri5<OrbitOdeState>().do_step(sys, y, t, h);
  } else {
    odeint::runge_kutta_fehlberg78<OrbitOdeState>().do_step(sys, y, t, h);
  }
  return from_orbit_ode(y);
}

}  // namespace

bool is_orbit_adaptive_method(std::string_view name) {
  return std::find(kAdaptive.begin(), kAdaptive.end(), name) != kAdaptive.end();
}

void validate_orbit_method(const MethodSettings& settings) {
  std::string names;
  for (const CompositionTable& t : composition_tables()) {
    if (t.name == settings.name) {
      if (!(settings.step > 0) || !std::isfinite(settings.step)) {
        throw InputError("step: method " + settings.name + " needs a finite step > 0, found " +
                         format_number(settings.step));
      }
      return;
    }
    names += std::string(t.name) + ", ";
  }
  if (!is_orbit_adaptive_method(settings.name)) {
    throw InputError("method: expected one of " + names +
                     "rkf78, dopri5, dop853, taylor on an orbit, found '" + settings.name + "'");
  }
  if (!(settings.abs_tol > 0) || !(settings.rel_tol > 0)) {
    throw InputError("tol: method " + settings.name + " needs tolerances > 0, found " +
                     format_number(settings.abs_tol));
  }
}

OrbitState rkf78_step(const CircularOrbitModel& model, const OrbitState& x, double t, double h) {
  return one_step(MethodSettings("rkf78"), model, x, t, h);
}

OrbitState rkf78_step(const EllipticOrbitModel& model, const OrbitState& x, double nu, double h) {
  return one_step(MethodSettings("rkf78"), model, x, nu, h);
}

OrbitState adaptive_formula_step(const MethodSettings& method, const CircularOrbitModel& model,
                                 const OrbitState& x, double t, double h) {
  return one_step(method, model, x, t, h);
}

OrbitState adaptive_formula_step(const MethodSettings& method, const EllipticOrbitModel& model,
                                 const OrbitState& x, double nu, double h) {
  return one_step(method, model, x, nu, h);
}

OrbitOutcome integrate_adaptive(const CircularOrbitModel& model, OrbitState x, double t0, double t1,
                                const OrbitAdaptiveOptions& options,
                                const OrbitObserver& observer) {
  return run_adaptive(model, x, t0, t1, options, observer);
}

OrbitOutcome integrate_adaptive(const EllipticOrbitModel& model, OrbitState x, double nu0,
                                double nu1, const OrbitAdaptiveOptions& options,
                                const OrbitObserver& observer) {
  return run_adaptive(model, x, nu0, nu1, options, observer);
}

OrbitOutcome run_orbit_method(const MethodSettings& settings, const CircularOrbitModel& model,
                              const OrbitState& x, double t0, double t1, std::int64_t max_steps,
                              const OrbitObserver& observer) {
  return run(settings, model, x, t0, t1, max_steps, observer);
}

OrbitOutcome run_orbit_method(const MethodSettings& settings, const EllipticOrbitModel& model,
                              const OrbitState& x, double nu0, double nu1, std::int64_t max_steps,
                              const OrbitObserver& observer) {
  return run(settings, model, x, nu0, nu1, max_steps, observer);
}

OrbitOutcome run_orbit_method_sampled(const MethodSettings& settings,
                                      const CircularOrbitModel& model, const OrbitState& x,
                                      double t0, double t1, const OutputTimes& times,
                                      std::int64_t max_steps, const OrbitSample& sample,
                                      const OrbitObserver& observer) {
  return run_sampled(settings, model, x, t0, t1, times, max_steps, sample, observer);
}

OrbitOutcome run_orbit_method_sampled(const MethodSettings& settings,
                                      const EllipticOrbitModel& model, const OrbitState& x,
                                      double nu0, double nu1, const OutputTimes& times,
                                      std::int64_t max_steps, const OrbitSample& sample,
                                      const OrbitObserver& observer) {
  return run_sampled(settings, model, x, nu0, nu1, times, max_steps, sample, observer);
}

}  // namespace newtop
