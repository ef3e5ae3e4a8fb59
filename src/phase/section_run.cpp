// One orbit's section on a Model: the template of section_run.hpp compiled once for every field.

#include "newtop/phase/section_run.hpp"

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

}  // namespace newtop::phase
