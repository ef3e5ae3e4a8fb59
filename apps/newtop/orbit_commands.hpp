#pragma once
// The subcommands on an orbit scenario (a file with [orbit], docs/cli.md "Orbit scenarios"):
// simulate, integrals, equilibria and stability call these when io::is_orbit_scenario says so;
// `stability --diagram debra-delp` writes the DeBra–Delp diagram.

#include <cstdint>
#include <optional>
#include <string>

namespace newtop::app {

struct OrbitSimulateArgs {
  std::optional<double> t_end, step, tol;
  std::optional<std::string> method, out;
  std::optional<std::int64_t> every;
  bool json = false;
};

int orbit_simulate(const std::string& path, const OrbitSimulateArgs& a);
int orbit_integrals(const std::string& path, bool json);
int orbit_equilibria(const std::string& path, bool json);
int orbit_stability(const std::string& path, bool json);

/// `--diagram NAME` (only "debra-delp"), over `--scan k_R=LO:HI:N,k_Y=LO:HI:M` (default
/// k_R, k_Y = -0.99:0.99:67), to the CSV `--out` and/or JSON.
int stability_diagram(const std::string& name, const std::optional<std::string>& scan,
                      const std::optional<std::string>& out, bool json);

}  // namespace newtop::app
