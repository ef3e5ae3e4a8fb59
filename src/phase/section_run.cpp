// One orbit's section on a Model: the template of section_run.hpp compiled once for every field.

#include "newtop/phase/section_run.hpp"

#include "newtop/exact/model_fields.hpp"
#include "newtop/integrate/method_settings.hpp"
#include "newtop/model/state_checks.hpp"

namespace newtop::phase {

SectionRun section_orbit(const MethodSettings& method, const Model& model, const SurfaceFunction& g,
                         const SectionSettings& settings, int orbit, const State& x0, double t0,
                         double t1, IntegrateOptions options, std::vector<Crossing>& out,
                         IntegralsDrift& drift, const std::function<void(double)>& on_step) {
  validate(x0);
  return visit_model(model, [&](const auto& m) {
    return section_orbit(method, m, g, settings, orbit, x0, t0, t1, options, out, drift, on_step);
  });
}

const char* to_string(SectionStatus s) {
  switch (s) {
    case SectionStatus::crossings:
      return "crossings";
    case SectionStatus::t_end:
      return "t_end";
    case SectionStatus::cap:
      return "cap";
    case SectionStatus::no_crossing:
      return "no_crossing";
    case SectionStatus::failed:
      return "failed";
  }
  return "failed";
}

SectionResult section(const Model& model, const State& x0, const SectionRequest& r) {
  validate(x0);
  require_body_surface(r.surface);
  IntegrateOptions options = r.options;
  double t1 = 0.0;
  if (r.t_end) {
    t1 = *r.t_end;
  } else {
    constexpr double kAdaptiveSpan = 1e12;
    if (method_info(r.method.name).kind == MethodKind::adaptive) {
      t1 = r.t0 + kAdaptiveSpan;
      options.min_step_factor /= kAdaptiveSpan;
    } else {
      t1 = r.t0 + 2.0 * static_cast<double>(options.max_steps) * r.method.step;
    }
  }
  check_time_span(r.t0, t1);
  const SurfaceFunction g(r.surface, model.body());
  const SectionSettings settings{r.direction, r.max_crossings, r.start_on_surface};
  SectionResult res;
  const SectionRun run = section_orbit(r.method, model, g, settings, r.orbit, x0, r.t0, t1, options,
                                       res.crossings, res.drift, r.on_step);
  res.outcome = run.outcome;
  res.max_residual = run.max_residual;
  res.max_relative = run.max_relative;
  const bool hit_cap = !r.t_end && run.outcome.status == Status::step_limit;
  if (run.by_crossings) {
    res.status = SectionStatus::crossings;
  } else if (run.outcome.status != Status::finished && !hit_cap) {
    res.status = SectionStatus::failed;
  } else if (res.crossings.empty()) {
    res.status = SectionStatus::no_crossing;
  } else {
    res.status = r.t_end ? SectionStatus::t_end : SectionStatus::cap;
  }
  return res;
}

}  // namespace newtop::phase
