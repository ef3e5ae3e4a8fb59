#include "newtop/io/orbit_settings.hpp"

#include <cmath>

#include "newtop/orbit/orbit_integrate.hpp"

namespace newtop::io {

MethodSettings resolve_method(const OrbitScenario& sc, const IntegrateOverrides& o) {
  const auto& f = sc.integrate;
  const std::optional<double> step = o.step ? o.step : (o.tol ? std::nullopt : f.step);
  const std::optional<double> tol = o.tol ? o.tol : (o.step ? std::nullopt : f.tol);
  MethodSettings m;
  m.name = o.method          ? *o.method
           : o.step || o.tol ? std::string(o.step ? kDefaultFixedMethod : kOrbitAdaptiveMethod)
           : f.method        ? *f.method
                             : std::string(step ? kDefaultFixedMethod : kOrbitAdaptiveMethod);
  MethodSettings probe = m;  // the name first: a method that does not run on an orbit
  probe.step = 1.0;
  validate_orbit_method(probe);
  if (is_orbit_adaptive_method(m.name)) {
    if (!tol) {
      throw InputError(sc.source + ": tol: method " + m.name + " needs --tol or [integrate] tol");
    }
    m.abs_tol = m.rel_tol = *tol;
  } else {
    if (!step) {
      throw InputError(sc.source + ": step: method " + m.name +
                       " needs --step or [integrate] step");
    }
    m.step = *step;
  }
  validate_orbit_method(m);
  return m;
}

double resolve_t_end(const OrbitScenario& sc, const IntegrateOverrides& o) {
  const std::optional<double> t_end = o.t_end ? o.t_end : sc.integrate.t_end;
  if (!t_end) throw InputError(sc.source + ": t_end: missing: give --t-end or [integrate] t_end");
  if (!std::isfinite(*t_end) || !(*t_end > sc.integrate.t0)) {
    throw InputError("t_end: expected a finite time > t0 = " + format_number(sc.integrate.t0) +
                     ", found " + format_number(*t_end));
  }
  return *t_end;
}

}  // namespace newtop::io
