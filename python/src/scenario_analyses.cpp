// chaos and section on a Scenario (read from a file or built in code): the [integrate] settings
// overridden by the keywords as the command line's --t-end, --method, --step, --tol and --split
// override them (io::resolve_method, io::resolve_t_end), so that newtop.chaos(path) and
// newtop.section(path) give the numbers of `newtop chaos` and `newtop section` bit for bit.

#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "analysis_results.hpp"
#include "bindings.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/model/state_checks.hpp"

namespace py = pybind11;

namespace newtop::python {

ChaosOut run_chaos(const MethodSettings& method, const Model& model, const State& state, double t0,
                   double t_end, const IntegrateOptions& options, bool spectrum, bool history) {
  phase::ChaosRequest r{
      .method = method, .t0 = t0, .t_end = t_end, .spectrum = spectrum, .options = options};
  ChaosOut out;
  out.method = method.name;
  if (history) r.history = [&out](const phase::ChaosSample& x) { out.history.push_back(x); };
  phase::check_chaos_request(r);
  check_time_span(t0, t_end);
  const py::gil_scoped_release unlocked;
  out.result = phase::chaos(model, state, r);
  return out;
}

SectionOut run_sections(const Model& model, const std::vector<State>& starts,
                        phase::SectionRequest request) {
  for (const State& x : starts) validate(x);
  SectionOut out{{}, {}, 0.0, "", model.body(), request.surface.text};
  bool all_by_crossings = !starts.empty();
  int capped = 0;
  {
    const py::gil_scoped_release unlocked;
    for (std::size_t k = 0; k < starts.size(); ++k) {
      request.orbit = static_cast<int>(k);
      const phase::SectionResult r = phase::section(model, starts[k], request);
      out.crossings.insert(out.crossings.end(), r.crossings.begin(), r.crossings.end());
      out.outcomes.push_back(r.outcome.status);
      const bool by_crossings = r.status == phase::SectionStatus::crossings;
      all_by_crossings = all_by_crossings && by_crossings;
      if (!request.t_end && !by_crossings) ++capped;
      out.max_residual = std::max(out.max_residual, r.max_residual);
    }
  }
  out.stopped_by = all_by_crossings ? "crossings" : capped > 0 ? "cap" : "t_end";
  return out;
}

namespace {

/// A run without t_end stops at its crossings or after this many steps (as `newtop section`
/// with --crossings and no t_end; [integrate] max_steps sets another).
constexpr std::int64_t kCrossingsStepCap = 1'000'000;

io::IntegrateOverrides overrides(std::optional<double> t_end,
                                 const std::optional<std::string>& method,
                                 std::optional<double> step, std::optional<double> tol,
                                 const std::optional<std::string>& split) {
  return {method, step, tol, t_end, split};
}

IntegrateOptions options_of(const io::Scenario& sc) {
  IntegrateOptions o;
  if (sc.integrate.max_steps) o.max_steps = *sc.integrate.max_steps;
  return o;
}

ChaosOut chaos_scenario(const io::Scenario& sc, const std::optional<State>& state,
                        std::optional<double> t_end, const std::optional<std::string>& method,
                        std::optional<double> step, std::optional<double> tol,
                        const std::optional<std::string>& split, bool spectrum, bool history) {
  const io::IntegrateOverrides ov = overrides(t_end, method, step, tol, split);
  const MethodSettings s = io::resolve_method(sc, ov);
  const double t1 = io::resolve_t_end(sc, ov);
  return run_chaos(s, sc.model, state.value_or(sc.initial), sc.integrate.t0, t1, options_of(sc),
                   spectrum, history);
}

SectionOut section_scenario(const io::Scenario& sc, const std::optional<std::vector<State>>& states,
                            std::optional<double> t_end, const std::string& surface,
                            std::int64_t crossings, const std::string& direction,
                            const std::optional<std::string>& method, std::optional<double> step,
                            std::optional<double> tol, const std::optional<std::string>& split,
                            std::optional<int> orbits, std::optional<double> energy,
                            std::optional<double> area) {
  const phase::Surface sf = phase::parse_surface(surface, "surface");
  phase::require_body_surface(sf, "surface");
  const phase::Direction dir = phase::parse_direction(direction, "direction");
  if (crossings < 1) {
    throw InputError("crossings: expected an integer >= 1, found " + std::to_string(crossings));
  }
  if ((energy || area) && !orbits) {
    throw InputError(std::string(energy ? "energy" : "area") +
                     ": the level of seeded orbits: needs orbits=K");
  }
  if (orbits && states) {
    throw InputError("orbits: seeds its own starts on the surface: not with states");
  }
  phase::SectionRequest q;
  q.surface = sf;
  q.direction = dir;
  q.max_crossings = crossings;
  q.start_on_surface = orbits.has_value();
  const io::IntegrateOverrides ov = overrides(t_end, method, step, tol, split);
  q.method = io::resolve_method(sc, ov);
  q.t0 = sc.integrate.t0;
  q.options = options_of(sc);
  if (t_end || sc.integrate.t_end) {
    q.t_end = io::resolve_t_end(sc, ov);
    check_time_span(q.t0, *q.t_end);
  } else {
    q.options.max_steps = sc.integrate.max_steps.value_or(kCrossingsStepCap);
  }
  std::vector<State> starts = states.value_or(std::vector<State>{sc.initial});
  if (orbits) {
    const phase::Levels levels{energy.value_or(newtop::energy(sc.model, sc.initial)),
                               area.value_or(newtop::area(sc.initial))};
    starts = phase::seed_orbits(sc.model, sf, levels, *orbits, dir);
  }
  return run_sections(sc.model, starts, q);
}

}  // namespace

void bind_scenario_analyses(py::module_& m) {
  m.def("_chaos_scenario", &chaos_scenario, py::arg("scenario"), py::kw_only(),
        py::arg("state") = py::none(), py::arg("t_end") = py::none(),
        py::arg("method") = py::none(), py::arg("step") = py::none(), py::arg("tol") = py::none(),
        py::arg("split") = py::none(), py::arg("spectrum") = false, py::arg("history") = false);
  m.def("_section_scenario", &section_scenario, py::arg("scenario"), py::kw_only(),
        py::arg("states") = py::none(), py::arg("t_end") = py::none(),
        py::arg("surface") = "gamma3 = 0", py::arg("crossings") = 1000, py::arg("direction") = "up",
        py::arg("method") = py::none(), py::arg("step") = py::none(), py::arg("tol") = py::none(),
        py::arg("split") = py::none(), py::arg("orbits") = py::none(),
        py::arg("energy") = py::none(), py::arg("area") = py::none());
}

}  // namespace newtop::python
