#pragma once
// The subcommands on an orbit scenario (a file with [orbit], docs/cli.md "Orbit scenarios"):
// simulate, integrals, equilibria and stability call these when io::is_orbit_scenario says so;
// `stability --diagram debra-delp` writes the DeBra–Delp diagram.

#include <cstdint>
#include <optional>
#include <string>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/io/orbit_scenario.hpp"

namespace newtop::app {

struct OrbitSimulateArgs {
  std::optional<double> t_end, step, tol, dt_out;
  std::optional<std::string> method, out, times, split;
  std::optional<std::int64_t> every;
  std::optional<int> euler;
  bool attitude = false;
  bool json = false;
};

/// As io::resolve_method: the command line's method, step or tolerance wins over the file's;
/// checked by validate_orbit_method.
MethodSettings orbit_method(const io::OrbitScenario& sc, const std::optional<std::string>& method,
                            std::optional<double> step, std::optional<double> tol);
/// --t-end over [integrate] t_end: finite and > t0, else InputError.
double orbit_t_end(const io::OrbitScenario& sc, std::optional<double> t_end);

/// newtop section on an orbit scenario (docs/section.md "Orbit scenarios"); the surface,
/// direction and crossings already checked by the caller.
struct OrbitSectionArgs {
  std::string scenario, surface, direction;
  std::optional<double> t_end, step, tol;
  std::optional<std::string> method, out;
  std::int64_t crossings = 1000;
  bool json = false;
};
int orbit_section_command(const OrbitSectionArgs& a);

/// newtop chaos on an orbit scenario (docs/orbit.md §13).
struct OrbitChaosArgs {
  std::string scenario;
  std::optional<double> t_end, step, tol;
  std::optional<std::string> method, split, out;
  bool spectrum = false;
  bool json = false;
};
int orbit_chaos_command(const OrbitChaosArgs& a);

int orbit_simulate(const std::string& path, const OrbitSimulateArgs& a);
int orbit_integrals(const std::string& path, bool json);
int orbit_equilibria(const std::string& path, bool json);
/// `equilibrium`: the K-th relative equilibrium of `newtop equilibria` instead of [initial].
int orbit_stability(const std::string& path, bool json, std::optional<int> equilibrium = {});

/// `--diagram NAME` (only "debra-delp"), over `--scan k_R=LO:HI:N,k_Y=LO:HI:M` (default
/// k_R, k_Y = -0.99:0.99:67), to the CSV `--out` and/or JSON.
int stability_diagram(const std::string& name, const std::optional<std::string>& scan,
                      const std::optional<std::string>& out, bool json);

}  // namespace newtop::app
