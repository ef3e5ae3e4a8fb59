// Orbit integrators by name, for scenario files and the command line.

#include <cmath>
#include <string>

#include "newtop/orbit/orbit_integrate.hpp"

namespace newtop {

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
  if (settings.name != "rkf78") {
    throw InputError("method: expected one of " + names + "rkf78 on an orbit, found '" +
                     settings.name + "'");
  }
  if (!(settings.abs_tol > 0) || !(settings.rel_tol > 0)) {
    throw InputError("tol: method rkf78 needs tolerances > 0, found " +
                     format_number(settings.abs_tol));
  }
}

namespace {

template <class M>
OrbitOutcome run(const MethodSettings& settings, const M& model, const OrbitState& x, double a,
                 double b, std::int64_t max_steps, const OrbitObserver& observer) {
  validate_orbit_method(settings);
  if (settings.name == "rkf78") {
    OrbitAdaptiveOptions options;
    options.abs_tol = settings.abs_tol;
    options.rel_tol = settings.rel_tol;
    options.max_steps = max_steps;
    return integrate_adaptive(model, x, a, b, options, observer);
  }
  const OrbitSplittingStepper stepper(composition_table(settings.name));
  return integrate(stepper, model, x, a, b, settings.step, observer);
}

}  // namespace

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

}  // namespace newtop
