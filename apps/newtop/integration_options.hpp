#pragma once
// The integration options every integrating command shares with `simulate`: --t-end, --method,
// --step, --tol over the scenario's [integrate], with the same defaults and the same errors.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::app {

struct IntegrationArgs {
  std::optional<double> t_end, step, tol;
  std::optional<std::string> method, split;
  io::IntegrateOverrides overrides() const { return {method, step, tol, t_end, split}; }
};

/// Adds --t-end, --method, --step, --tol (--step excludes --tol) and --split.
void add_integration_options(CLI::App& sub, std::optional<double>& t_end,
                             std::optional<std::string>& method, std::optional<double>& step,
                             std::optional<double>& tol, std::optional<std::string>& split);
inline void add_integration_options(CLI::App& sub, IntegrationArgs& a) {
  add_integration_options(sub, a.t_end, a.method, a.step, a.tol, a.split);
}

/// The free-body split a splitting method runs with ("axes", "spin", "exact"); none for the others.
std::optional<std::string> split_of(const MethodSettings& method);

/// The run from the scenario's t0 to t_end with `method`: non-finite times, a run of no length,
/// and a fixed-step run of more steps than max_steps are bad input (InputError).
void check_run_span(const io::Scenario& sc, const MethodSettings& method, double t0, double t_end,
                    const IntegrateOptions& options);

/// A resolved run: the method, t0, t_end and the driver's options ([integrate] max_steps).
struct RunSettings {
  MethodSettings method;
  double t0 = 0, t_end = 0;
  IntegrateOptions options;
};

/// io::load_scenario for the commands of the fixed-centre model only: an orbit scenario
/// (docs/orbit.md) is bad input, named as such.
io::Scenario load_body_scenario(const std::string& path);

/// resolve_method, resolve_t_end and check_run_span, as `simulate` does them.
RunSettings resolve_run(const io::Scenario& sc, const IntegrationArgs& a);

}  // namespace newtop::app
