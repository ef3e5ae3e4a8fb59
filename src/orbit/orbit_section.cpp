// Poincaré sections of the orbit model (orbit_section.hpp): the section observer of
// phase/section_run.hpp on the orbit steppers' one-step maps.

#include "newtop/orbit/orbit_section.hpp"

#include <cmath>
#include <cstddef>
#include <type_traits>

#include "newtop/model/attitude.hpp"
#include "newtop/phase/section_run.hpp"

namespace newtop {

void OrbitSectionDrift::observe(const OrbitState& x, const double* jacobi_value) {
  const OrbitCasimirs c = casimirs(x);
  if (!started) {
    started = true;
    has_jacobi = jacobi_value != nullptr;
    if (has_jacobi) jacobi0 = *jacobi_value;
    casimirs0 = c;
    return;
  }
  auto upd = [](double& m, double a, double b) { m = std::max(m, std::abs(a - b)); };
  if (has_jacobi && jacobi_value) upd(jacobi, *jacobi_value, jacobi0);
  upd(gamma_gamma, c.gamma_gamma, casimirs0.gamma_gamma);
  upd(normal_normal, c.normal_normal, casimirs0.normal_normal);
  upd(gamma_normal, c.gamma_normal, casimirs0.gamma_normal);
}

void OrbitSectionDrift::merge(const OrbitSectionDrift& other) {
  if (!other.started) return;
  if (!started) {
    *this = other;
    return;
  }
  jacobi = std::max(jacobi, other.jacobi);
  gamma_gamma = std::max(gamma_gamma, other.gamma_gamma);
  normal_normal = std::max(normal_normal, other.normal_normal);
  gamma_normal = std::max(gamma_normal, other.gamma_normal);
}

namespace {

/// One orbit's section with the method's one-step map `step(x, t, τ)` (a splitting step or one
/// step of rkf78's formula) and the run `run_method(observer)`.
template <class M, class Step, class Jacobi>
phase::SectionRun section_with(const MethodSettings& method, const M& model, Step step,
                               Jacobi jacobi, const phase::SurfaceFunction& g,
                               const phase::SectionSettings& settings, int orbit,
                               const OrbitState& x0, double a, double b, std::int64_t max_steps,
                               std::vector<OrbitCrossing>& out, OrbitSectionDrift& drift,
                               const std::function<void(double)>& on_step) {
  validate_orbit_method(method);
  phase::SectionRun run;
  auto watch = [&](const OrbitState& x) {
    if constexpr (std::is_same_v<Jacobi, std::nullptr_t>) {
      drift.observe(x, nullptr);
    } else {
      const double j = jacobi(x);
      drift.observe(x, &j);
    }
  };
  auto seen = [&](double t, const OrbitState&) {
    if (on_step) on_step(t);
  };
  auto drive = [&](auto&& observer) {
    const OrbitObserver obs = [&](double t, const OrbitState& x) {
      // Kept in the outcome as the run goes, so that a run stopped by the crossings reports
      // where it stopped.
      run.outcome.t = t;
      observer(t, x);
    };
    const OrbitOutcome o = run_orbit_method(method, model, x0, a, b, max_steps, obs);
    run.outcome.status = o.status;
    run.outcome.t = o.t;
    run.outcome.steps = o.steps;
    run.outcome.rejected = o.rejected;
  };
  if (phase::detail::observe_section<OrbitState>(std::move(step), g, watch, settings, orbit, out,
                                                 run, drive, seen)) {
    run.by_crossings = true;
    run.outcome.status = Status::finished;
  }
  return run;
}

}  // namespace

phase::SectionRun orbit_section(const MethodSettings& method, const CircularOrbitModel& model,
                                const phase::SurfaceFunction& g,
                                const phase::SectionSettings& settings, int orbit,
                                const OrbitState& x0, double t0, double t1, std::int64_t max_steps,
                                std::vector<OrbitCrossing>& out, OrbitSectionDrift& drift,
                                const std::function<void(double)>& on_step) {
  auto jacobi = [&](const OrbitState& x) { return jacobi_integral(model, x); };
  if (is_orbit_adaptive_method(method.name)) {
    auto step = [&](double t, const OrbitState& x, double tau) {
      return adaptive_formula_step(method, model, x, t, tau);
    };
    return section_with(method, model, step, jacobi, g, settings, orbit, x0, t0, t1, max_steps, out,
                        drift, on_step);
  }
  validate_orbit_method(method);
  const OrbitSplittingStepper stepper(composition_table(method.name));
  auto step = [&](double, const OrbitState& x, double tau) {
    OrbitState y = x;
    stepper.step(model, y, tau);
    return y;
  };
  return section_with(method, model, step, jacobi, g, settings, orbit, x0, t0, t1, max_steps, out,
                      drift, on_step);
}

phase::SectionRun orbit_section(const MethodSettings& method, const EllipticOrbitModel& model,
                                const phase::SurfaceFunction& g,
                                const phase::SectionSettings& settings, int orbit,
                                const OrbitState& x0, double nu0, double nu1,
                                std::int64_t max_steps, std::vector<OrbitCrossing>& out,
                                OrbitSectionDrift& drift,
                                const std::function<void(double)>& on_step) {
  if (is_orbit_adaptive_method(method.name)) {
    auto step = [&](double nu, const OrbitState& x, double tau) {
      return adaptive_formula_step(method, model, x, nu, tau);
    };
    return section_with(method, model, step, nullptr, g, settings, orbit, x0, nu0, nu1, max_steps,
                        out, drift, on_step);
  }
  validate_orbit_method(method);
  const OrbitSplittingStepper stepper(composition_table(method.name));
  auto step = [&](double nu, const OrbitState& x, double tau) {
    OrbitState y = x;
    stepper.step(model, y, nu, tau);
    return y;
  };
  return section_with(method, model, step, nullptr, g, settings, orbit, x0, nu0, nu1, max_steps,
                      out, drift, on_step);
}

OrbitFrameCoords orbit_frame_coords(const Body& body, const OrbitState& x, double orbit_rate) {
  // Body axes in orbital components: the transpose of the orbital frame in body components.
  const Mat3 R = orbital_frame(x).transpose();
  return {euler_321(Quaternion(R)), relative_omega(body, x, orbit_rate)};
}

namespace {

/// The end of the request's span (required on an orbit), checked.
double orbit_span_end(const phase::SectionRequest& r) {
  if (!r.t_end) {
    throw InputError("t_end: a section on an orbit runs to t_end; none given");
  }
  check_time_span(r.t0, *r.t_end);
  if (!(*r.t_end > r.t0)) {
    throw InputError("t_end: expected a time after t0 = " + format_number(r.t0) + ", found " +
                     format_number(*r.t_end));
  }
  return *r.t_end;
}

template <class M>
OrbitSectionResult section_of(const M& model, const OrbitState& x0, const phase::SectionRequest& r,
                              double a, double b) {
  validate_orbit_method(r.method);
  const phase::SurfaceFunction g(r.surface, model.body(), /*with_normal=*/true);
  const phase::SectionSettings settings{r.direction, r.max_crossings, r.start_on_surface};
  OrbitSectionResult res;
  const phase::SectionRun run =
      orbit_section(r.method, model, g, settings, r.orbit, x0, a, b, r.options.max_steps,
                    res.crossings, res.drift, r.on_step);
  res.outcome = run.outcome.status;
  res.reached = run.outcome.t;
  res.steps = run.outcome.steps;
  res.rejected = run.outcome.rejected;
  res.max_residual = run.max_residual;
  res.max_relative = run.max_relative;
  if (run.by_crossings) {
    res.status = phase::SectionStatus::crossings;
  } else if (run.outcome.status != Status::finished) {
    res.status = phase::SectionStatus::failed;
  } else {
    res.status =
        res.crossings.empty() ? phase::SectionStatus::no_crossing : phase::SectionStatus::t_end;
  }
  return res;
}

}  // namespace

OrbitSectionResult orbit_section(const CircularOrbitModel& model, const OrbitState& x0,
                                 const phase::SectionRequest& request) {
  return section_of(model, x0, request, request.t0, orbit_span_end(request));
}

OrbitSectionResult orbit_section(const EllipticOrbitModel& model, const OrbitState& x0,
                                 const phase::SectionRequest& request) {
  const EllipticOrbit& e = model.orbit();
  const double nu1 = true_anomaly_at(e, orbit_span_end(request) - request.t0);
  return section_of(model, x0, request, e.true_anomaly0, nu1);
}

}  // namespace newtop
