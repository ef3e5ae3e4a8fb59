// The integration options shared with `simulate` (integration_options.hpp).

#include "integration_options.hpp"

#include "newtop/io/orbit_scenario.hpp"

namespace newtop::app {

void add_integration_options(CLI::App& sub, std::optional<double>& t_end,
                             std::optional<std::string>& method, std::optional<double>& step,
                             std::optional<double>& tol, std::optional<std::string>& split) {
  sub.add_option("--t-end", t_end, "final time (overrides [integrate] t_end)");
  sub.add_option("--method", method,
                 "method: splitting2, splitting4, splitting4-yoshida, splitting6, splitting8, "
                 "splitting8-mclachlan, rk4, dopri5, rkf78, dop853, taylor (quadratic field)");
  auto* s = sub.add_option("--step", step, "fixed step (selects splitting6 by default)");
  auto* t =
      sub.add_option("--tol", tol,
                     "absolute and relative tolerance (selects taylor by default on the quadratic "
                     "field, dop853 on the others)");
  s->excludes(t);
  sub.add_option("--split", split,
                 "free-body split of the splitting methods: axes, spin or exact (overrides "
                 "[integrate] split; docs/methods.md)");
}

void check_run_span(const io::Scenario& sc, const MethodSettings& method, double t0, double t_end,
                    const IntegrateOptions& options) {
  check_time_span(t0, t_end);
  if (t_end == t0) {
    throw InputError("t_end: expected a time different from t0 = " + format_number(t0) +
                     ", found " + format_number(t_end) + " (a run of no length)");
  }
  if (method_info(method.name).kind == MethodKind::adaptive) return;
  const std::int64_t n = fixed_step_count(t0, t_end, method.step);
  if (n > options.max_steps) {
    throw InputError("step: the run from t0 = " + format_number(t0) +
                     " to t_end = " + format_number(t_end) + " at step " +
                     format_number(method.step) + " takes " + std::to_string(n) +
                     " steps, more than max_steps = " + std::to_string(options.max_steps) +
                     (sc.integrate.max_steps ? " ([integrate] max_steps)" : " (the default)"));
  }
}

RunSettings resolve_run(const io::Scenario& sc, const IntegrationArgs& a) {
  RunSettings r;
  const io::IntegrateOverrides ov = a.overrides();
  r.method = io::resolve_method(sc, ov);
  r.t0 = sc.integrate.t0;
  r.t_end = io::resolve_t_end(sc, ov);
  if (sc.integrate.max_steps) r.options.max_steps = *sc.integrate.max_steps;
  check_run_span(sc, r.method, r.t0, r.t_end, r.options);
  return r;
}

io::Scenario load_body_scenario(const std::string& path) {
  if (io::is_orbit_scenario(path)) {
    throw InputError(
        "scenario: expected a body scenario ([body], [field], [initial]), found an "
        "orbit scenario ([orbit])");
  }
  return io::load_scenario(path);
}

std::optional<std::string> split_of(const MethodSettings& method) {
  if (method_info(method.name).kind != MethodKind::splitting) return std::nullopt;
  return std::string(to_string(free_body_split(method)));
}

}  // namespace newtop::app
