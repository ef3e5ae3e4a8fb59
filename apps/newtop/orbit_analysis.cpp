// newtop equilibria / stability on an orbit scenario (relative equilibria on a circular orbit and
// their linear stability), and `newtop stability --diagram debra-delp`.

#include <cmath>
#include <iostream>
#include <memory>

#include "newtop/io/json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/debra_delp.hpp"
#include "newtop/orbit/lvlh.hpp"
#include "newtop/orbit/orbit_equilibria.hpp"
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

io::Json eigen_json(const RelativeSpectrum& sp) {
  io::Json list = io::Json::array();
  for (const auto& z : sp.eigenvalues) list.push_back({z.real(), z.imag()});
  return list;
}

/// The keys of the fixed-centre `stability` report: lyapunov_stable is true where the Jacobi
/// integral is a strict minimum on the leaf, false where unstable, null where only gyroscopic.
void add_stability(io::Json& j, const RelativeSpectrum& sp) {
  j["eigenvalues"] = eigen_json(sp);
  j["max_real_part"] = sp.max_real_part;
  j["linearly_stable"] = sp.linearly_stable;
  j["lyapunov_stable"] = sp.verdict == OrbitStability::lyapunov   ? io::Json(true)
                         : sp.verdict == OrbitStability::unstable ? io::Json(false)
                                                                  : io::Json(nullptr);
  j["verdict"] = to_string(sp.verdict);
}

}  // namespace

int orbit_equilibria(const std::string& path, bool json) {
  const io::OrbitScenario sc = io::load_orbit_scenario(path);
  warn_units(sc);
  const RelativeEquilibriumSet set = find_relative_equilibria(circular_model(sc, "equilibria"));
  io::Json list = io::Json::array();
  int number = 0;
  for (const auto& e : set.equilibria) {
    const Mat3 C = lvlh_to_body(OrbitState{Vec3::Zero(), e.gamma, e.normal});
    io::Json j{{"number", ++number},
               {"gamma", io::to_json(e.gamma)},
               {"normal", io::to_json(e.normal)},
               {"lvlh_quaternion", scalar_first(lvlh_quaternion(C))},
               {"roll_pitch_yaw", io::to_json(roll_pitch_yaw(C))},
               {"jacobi", e.jacobi},
               {"residual", e.residual}};
    add_stability(j, e.stability);
    list.push_back(j);
  }
  io::Json j{{"equilibria", list},       {"count", set.equilibria.size()},
             {"lyapunov", set.lyapunov}, {"gyroscopic", set.gyroscopic},
             {"unstable", set.unstable}, {"model", orbit_model_json(sc)}};
  if (json) {
    print_json(std::cout, j);
    return 0;
  }
  std::cout << "newtop equilibria " << sc.source << "\n";
  print_orbit_model(std::cout, sc);
  std::cout << set.equilibria.size() << " relative equilibria (" << set.lyapunov << " Lyapunov, "
            << set.gyroscopic << " gyroscopic, " << set.unstable << " unstable)\n";
  for (const auto& e : list) {
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
  if (equilibrium) {
    // --equilibrium K: the K-th (1-based) of `newtop equilibria`'s list, at rest in the frame.
    const RelativeEquilibriumSet set = find_relative_equilibria(model);
    const int n = static_cast<int>(set.equilibria.size());
    if (*equilibrium < 1 || *equilibrium > n) {
      throw InputError("--equilibrium: expected 1 to " + std::to_string(n) +
                       " (newtop equilibria " + sc.source + "), found " +
                       std::to_string(*equilibrium));
    }
    const RelativeEquilibrium& e = set.equilibria[static_cast<std::size_t>(*equilibrium - 1)];
    sc.initial = relative_rest_state(model, e.gamma, e.normal);
  }
  const double res = fixed_point_residual(model, sc.initial);
  if (!(res <= kRelativeEquilibriumTolerance)) {
    throw InputError(
        sc.source + ": [initial]: expected a relative equilibrium (relative residual " +
        "of d(m, gamma, normal)/dt <= " + format_number(kRelativeEquilibriumTolerance) +
        "), found residual " + format_number(res) + "; see newtop equilibria");
  }
  const RelativeSpectrum sp = relative_equilibrium_stability(model, sc.initial);
  io::Json j;
  add_stability(j, sp);
  j["characteristic_polynomial"] = io::Json::array();
  for (int k = 0; k < 7; ++k) j["characteristic_polynomial"].push_back(sp.characteristic[k]);
  j["omega"] = io::to_json(omega(sc.body, sc.initial));
  j["gamma"] = io::to_json(sc.initial.gamma);
  j["normal"] = io::to_json(sc.initial.normal);
  j["jacobi"] = jacobi_integral(model, sc.initial);
  j["residual"] = res;
  j["model"] = orbit_model_json(sc);
  if (json) {
    print_json(std::cout, j);
    return 0;
  }
  std::cout << "newtop stability " << sc.source << "\n";
  print_orbit_model(std::cout, sc);
  std::cout << "state     gamma = " << format_vector(sc.initial.gamma)
            << "  normal = " << format_vector(sc.initial.normal) << "  (fixed-point residual "
            << format_number(res) << ")\neigenvalues on the symplectic leaf:";
  for (const auto& z : sp.eigenvalues) {
    std::cout << "  " << format_number(z.real()) << (z.imag() < 0 ? "" : "+")
              << format_number(z.imag()) << "i";
  }
  std::cout << "\nlinear (spectral) stability: " << (sp.linearly_stable ? "stable" : "unstable")
            << "\nverdict: " << to_string(sp.verdict) << "\n";
  return 0;
}

int stability_diagram(const std::string& name, const std::optional<std::string>& scan,
                      const std::optional<std::string>& out, bool json) {
  if (name != "debra-delp") {
    throw InputError("--diagram: expected debra-delp, found '" + name + "'");
  }
  const auto [r, y] =
      scan ? io::parse_ratio_scan(*scan) : std::pair<io::RatioAxis, io::RatioAxis>{};
  const std::vector<DebraDelpPoint> points = debra_delp_scan(r.lo, r.hi, r.n, y.lo, y.hi, y.n);
  std::unique_ptr<io::AtomicFile> file;
  if (out) {
    file = std::make_unique<io::AtomicFile>(*out);
    file->stream() << "k_R,k_Y,region,closed_form,boundary,max_real_part\n";
  }
  io::Json list = io::Json::array();
  int count[3] = {0, 0, 0}, disagree = 0;
  for (const auto& p : points) {
    ++count[static_cast<int>(p.computed)];
    disagree += !p.boundary && p.computed != p.closed_form;
    if (file) {
      file->stream() << format_number(p.k_R) << ',' << format_number(p.k_Y) << ','
                     << to_string(p.computed) << ',' << to_string(p.closed_form) << ','
                     << (p.boundary ? "true" : "false") << ',' << format_number(p.max_real_part)
                     << '\n';
    }
    if (json) {
      list.push_back({{"k_R", p.k_R},
                      {"k_Y", p.k_Y},
                      {"region", to_string(p.computed)},
                      {"closed_form", to_string(p.closed_form)},
                      {"boundary", p.boundary},
                      {"max_real_part", p.max_real_part}});
    }
  }
  if (file) file->commit();
  if (json) {
    io::Json j{
        {"diagram", "debra-delp"},
        {"parameters",
         "k_R = (B - C)/A, k_Y = (B - A)/C; A roll (velocity), B pitch "
         "(orbit normal), C yaw (radius)"},
        {"points", list},
        {"counts", {{"lagrange", count[0]}, {"debra_delp", count[1]}, {"unstable", count[2]}}},
        {"disagreements_with_closed_form", disagree}};
    if (out) j["csv"] = *out;
    print_json(std::cout, j);
    return 0;
  }
  std::cout << "newtop stability --diagram debra-delp: " << points.size() << " points\n"
            << "  lagrange " << count[0] << "   debra_delp " << count[1] << "   unstable "
            << count[2] << "\n  off-boundary points disagreeing with the closed form: " << disagree
            << "\n";
  if (out) std::cout << "diagram written to " << *out << "\n";
  return 0;
}

}  // namespace newtop::app
