// newtop equilibria / stability on an orbit scenario (relative equilibria on a circular orbit and
// their linear stability), and `newtop stability --diagram debra-delp`.

#include <cmath>
#include <iostream>
#include <memory>

#include "newtop/io/json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/orbit_json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/orbit_equilibria.hpp"
#include "newtop/orbit/orbit_reports.hpp"
#include "orbit_commands.hpp"
#include "orbit_summary.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

CircularOrbitModel circular_model(const io::OrbitScenario& sc, const char* command) {
  if (!sc.circular()) {
    throw InputError(sc.source + ": [orbit] kind: " + command +
                     " needs kind = \"circular\" (relative equilibria are at rest in a uniformly "
                     "turning frame), found \"elliptic\"");
  }
  return CircularOrbitModel(sc.body, std::get<CircularOrbit>(sc.orbit));
}

}  // namespace

int orbit_equilibria(const std::string& path, bool json) {
  const io::OrbitScenario sc = io::load_orbit_scenario(path);
  warn_units(sc);
  const RelativeEquilibriumSet set = find_relative_equilibria(circular_model(sc, "equilibria"));
  io::Json j = io::to_json(set);
  j["model"] = orbit_model_json(sc);
  if (json) {
    print_json(std::cout, j);
    return 0;
  }
  std::cout << "newtop equilibria " << sc.source << "\n";
  print_orbit_model(std::cout, sc);
  std::cout << set.equilibria.size() << " relative equilibria (" << set.lyapunov << " Lyapunov, "
            << set.gyroscopic << " gyroscopic, " << set.unstable << " unstable)\n";
  for (const auto& e : j["equilibria"]) {
    std::cout << "  " << e["number"].get<int>() << "  gamma = " << e["gamma"].dump()
              << "  normal = " << e["normal"].dump()
              << "  roll,pitch,yaw = " << e["roll_pitch_yaw"].dump()
              << "  q = " << e["lvlh_quaternion"].dump()
              << "  jacobi = " << format_number(e["jacobi"].get<double>()) << "  "
              << e["verdict"].get<std::string>() << "\n";
  }
  return 0;
}

int orbit_stability(const std::string& path, bool json, std::optional<int> equilibrium) {
  io::OrbitScenario sc = io::load_orbit_scenario(path);
  warn_units(sc);
  const CircularOrbitModel model = circular_model(sc, "stability");
  // --equilibrium K: the K-th (1-based) of `newtop equilibria`'s list; else [initial].
  const RelativeStabilityReport r = relative_stability(
      model, equilibrium ? RelativeStabilityRequest{equilibrium, std::nullopt, "--equilibrium"}
                         : RelativeStabilityRequest{std::nullopt, sc.initial, "--equilibrium",
                                                    sc.source + ": [initial]"});
  sc.initial = r.state;  // the model's summary (its libration modes) at the analysed state
  io::Json j = io::to_json(r);
  j["model"] = orbit_model_json(sc);
  if (json) {
    print_json(std::cout, j);
    return 0;
  }
  std::cout << "newtop stability " << sc.source << "\n";
  print_orbit_model(std::cout, sc);
  std::cout << "state     gamma = " << format_vector(r.state.gamma)
            << "  normal = " << format_vector(r.state.normal) << "  (fixed-point residual "
            << format_number(r.residual) << ")\neigenvalues on the symplectic leaf:";
  for (const auto& z : r.spectrum.eigenvalues) {
    std::cout << "  " << format_number(z.real()) << (z.imag() < 0 ? "" : "+")
              << format_number(z.imag()) << "i";
  }
  std::cout << "\nlinear (spectral) stability: "
            << (r.spectrum.linearly_stable ? "stable" : "unstable")
            << "\nverdict: " << to_string(r.spectrum.verdict) << "\n";
  return 0;
}

int stability_diagram(const std::string& name, const std::optional<std::string>& scan,
                      const std::optional<std::string>& out, bool json) {
  if (name != "debra-delp") {
    throw InputError("--diagram: expected debra-delp, found '" + name + "'");
  }
  const auto [r, y] =
      scan ? io::parse_ratio_scan(*scan) : std::pair<io::RatioAxis, io::RatioAxis>{};
  const DebraDelpDiagram d =
      debra_delp_diagram(RatioRange{r.lo, r.hi, r.n}, RatioRange{y.lo, y.hi, y.n});
  if (out) {
    io::AtomicFile file(*out);
    io::write_csv(file.stream(), d);
    file.commit();
  }
  if (json) {
    io::Json j = io::to_json(d);
    if (out) j["csv"] = *out;
    print_json(std::cout, j);
    return 0;
  }
  std::cout << "newtop stability --diagram debra-delp: " << d.points.size() << " points\n"
            << "  lagrange " << d.counts[0] << "   debra_delp " << d.counts[1] << "   unstable "
            << d.counts[2] << "\n  off-boundary points disagreeing with the closed form: "
            << d.disagreements_with_closed_form << "\n";
  if (out) std::cout << "diagram written to " << *out << "\n";
  return 0;
}

}  // namespace newtop::app
