// newtop stability SCENARIO.toml: linear and energy–Casimir stability of the scenario's initial
// state (an equilibrium or a permanent rotation) or of the spin --axis/--omega (docs/model.md
// §7–§9); stability diagrams along Ω (--scan-omega) or over two parameters (--scan).

#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "orbit_commands.hpp"
#include "stability_scan.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct StabilityArgs {
  std::string scenario;
  std::optional<std::string> axis, scan_omega, scan, out, diagram;
  std::optional<double> omega;
  std::optional<int> equilibrium;  // 1-based, as `newtop equilibria` numbers its list
  bool json = false;
};

/// The state analysed, where it came from, and its polishing by Newton's method.
struct Chosen {
  State state;
  std::optional<int> axis;  // the principal axis of a spin γ = e_axis, ω ∥ e_axis
  PolishedFixedPoint polish;
};

std::optional<int> parse_axis(const std::optional<std::string>& axis) {
  if (!axis) return std::nullopt;
  if (*axis == "x") return 0;
  if (*axis == "y") return 1;
  if (*axis == "z") return 2;
  throw InputError("--axis: expected x, y or z, found '" + *axis + "'");
}

/// The principal axis i with γ = e_i and ω ∥ e_i (or ω = 0), where the spin family about it is a
/// fixed point for every Ω (M g r0 along e_i).
std::optional<int> spin_axis_of(const QuadraticModel& model, const State& s) {
  const Vec3 w = omega(model.body, s);
  const Vec3 b = model.body.mass() * model.field.g * model.body.center_of_mass();
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = Vec3::Unit(i);
    if ((s.gamma - e).norm() <= kFixedPointTolerance &&
        w.cross(e).norm() <= kFixedPointTolerance * std::max(w.norm(), 1.0) &&
        b.cross(e).norm() <= kFixedPointTolerance * b.norm()) {
      return i;
    }
  }
  return std::nullopt;
}

/// A number, or `missing` when the JSON value is null (never "null" in a human summary).
std::string optional_text(const io::Json& v, const std::string& missing) {
  return v.is_null() ? missing : format_number(v.get<double>());
}

Vec3 vec(const io::Json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

/// --equilibrium K: the K-th (1-based) isolated equilibrium of `newtop equilibria`, at rest.
State listed_equilibrium(const io::Scenario& sc, int k) {
  const EquilibriumSet set = find_equilibria(sc.model);
  const int count = static_cast<int>(set.equilibria.size());
  if (count == 0) {
    throw InputError("--equilibrium: " + sc.source + " has no isolated equilibrium" +
                     (set.every_orientation ? " (every orientation is an equilibrium)" : ""));
  }
  if (k < 1 || k > count) {
    throw InputError("--equilibrium: expected 1 to " + std::to_string(count) +
                     " (the equilibria listed by newtop equilibria), found " + std::to_string(k));
  }
  return state_from_omega(sc.model.body(), Vec3::Zero(), set.equilibria[k - 1].gamma);
}

/// The state to analyse: --axis (exact), --equilibrium or [initial] (polished by Newton).
Chosen chosen_state(const io::Scenario& sc, const StabilityArgs& a) {
  const std::optional<int> axis = parse_axis(a.axis);
  if (a.omega && !axis) throw InputError("--omega: needs --axis x|y|z to say which axis spins");
  if (a.equilibrium && axis) throw InputError("--equilibrium: give either --equilibrium or --axis");
  if (axis) {
    const State s = principal_spin(sc.model.body(), *axis, a.omega.value_or(0.0));
    const double res = fixed_point_residual(sc.model, s);
    if (!(res <= kFixedPointTolerance)) {
      throw InputError("--axis " + *a.axis + ": expected a permanent rotation, found residual " +
                       format_number(res) + " of d(m, gamma)/dt (M g r0 is not along the axis)");
    }
    return {s, axis, polish_fixed_point(sc.model, s)};
  }
  const State given = a.equilibrium ? listed_equilibrium(sc, *a.equilibrium) : sc.initial;
  const PolishedFixedPoint p = polish_fixed_point(sc.model, given);
  if (!p.converged) {
    throw InputError(
        (a.equilibrium ? "--equilibrium " + std::to_string(*a.equilibrium)
                       : sc.source + ": [initial]") +
        ": expected an equilibrium or a permanent rotation (to " +
        "three digits or more), found residual " + format_number(p.residual_given) +
        " of d(m, gamma)/dt, and " +
        (p.iterations == 0 ? std::string("Newton's method finds no fixed point near it")
         : p.correction > kPolishRadius
             ? "the fixed point Newton's method finds is " + format_number(p.correction) +
                   " away (more than " + format_number(kPolishRadius) + ")"
             : "Newton's method stops at residual " + format_number(p.residual)) +
        "; see newtop equilibria (and --equilibrium K) / rotations, or use --axis and --omega");
  }
  // The spin families about principal axes (and their thresholds) are the quadratic field's.
  const std::optional<int> spin_axis = sc.model.kind() == FieldKind::quadratic
                                           ? spin_axis_of(sc.model.quadratic(), p.state)
                                           : std::nullopt;
  return {p.state, spin_axis, p};
}

io::Json report(const io::Scenario& sc, const Chosen& c) {
  // The field's own linearisation; the spin thresholds only with an axis (the quadratic field).
  const State& s = c.state;
  const std::optional<int> axis = c.axis;
  const Spectrum sp = linear_stability(sc.model, s);
  io::Json j;
  j["eigenvalues"] = io::Json::array();
  for (const auto& z : sp.eigenvalues) j["eigenvalues"].push_back({z.real(), z.imag()});
  j["max_real_part"] = sp.max_real_part;
  j["linearly_stable"] = sp.linearly_stable;
  j["lyapunov_stable"] = optional_json(sp.lyapunov_stable);
  const Body& body = sc.model.body();
  std::optional<double> formula, numeric;
  if (axis) {
    const QuadraticModel& m = sc.model.quadratic();
    const bool no_offset = m.body.mass() * m.field.g * m.body.center_of_mass().norm() == 0.0;
    if (no_offset) formula = beletsky_threshold(m.body, m.field.lambda_, *axis);
    numeric = numeric_threshold(m, *axis);
  }
  j["threshold_omega_formula"] = optional_json(formula);
  j["threshold_omega_numeric"] = optional_json(numeric);
  j["axis"] = axis ? io::Json(std::string(1, "xyz"[*axis])) : io::Json(nullptr);
  j["axis_class"] = axis ? io::Json(to_string(axis_class(body, *axis))) : io::Json(nullptr);
  j["omega"] = io::to_json(omega(body, s));
  j["gamma"] = io::to_json(s.gamma);
  j["residual"] = fixed_point_residual(sc.model, s);
  j["polish"] = {{"residual_given", c.polish.residual_given},
                 {"correction", c.polish.correction},
                 {"iterations", c.polish.iterations}};
  return j;
}

std::string complex_text(const io::Json& z) {
  const double im = z[1].get<double>();
  return format_number(z[0].get<double>()) + (im < 0 ? "-" : "+") + format_number(std::abs(im)) +
         "i";
}

void print_report(std::ostream& os, const io::Json& j) {
  const io::Json& p = j["polish"];
  if (p["iterations"].get<int>() > 0) {
    os << "polished  by Newton's method: correction "
       << format_number(p["correction"].get<double>()) << " (residual "
       << format_number(p["residual_given"].get<double>()) << " -> "
       << format_number(j["residual"].get<double>()) << " in " << p["iterations"].get<int>()
       << (p["iterations"].get<int>() == 1 ? " step" : " steps") << ")\n";
  }
  os << "state     omega = " << format_vector(vec(j["omega"]))
     << "  gamma = " << format_vector(vec(j["gamma"])) << "  (fixed-point residual "
     << format_number(j["residual"].get<double>()) << ")\n";
  os << "eigenvalues on the symplectic leaf:";
  for (const auto& z : j["eigenvalues"]) os << "  " << complex_text(z);
  os << "\nmax real part " << format_number(j["max_real_part"].get<double>())
     << "\nlinear (spectral) stability: "
     << (j["linearly_stable"].get<bool>() ? "stable" : "unstable")
     << "\nLyapunov (energy-Casimir): " << verdict_text(optional_bool(j["lyapunov_stable"]))
     << "\n";
  if (!j["axis"].is_null()) {
    os << "spin axis " << j["axis"].get<std::string>() << " (" << j["axis_class"].get<std::string>()
       << " moment); threshold Omega: formula "
       << optional_text(j["threshold_omega_formula"],
                        "not applicable (largest-moment axis, r0 = 0, lambda > 0 only)")
       << ", numeric "
       << optional_text(j["threshold_omega_numeric"], "none (no unstable-to-stable change)")
       << "\n";
  }
}

int run(const StabilityArgs& a) {
  if (a.diagram) {
    if (!a.scenario.empty() || a.axis || a.omega || a.scan_omega || a.equilibrium) {
      throw InputError(
          "--diagram: takes no scenario, --axis, --omega, --equilibrium or --scan-omega (only "
          "--scan, "
          "--out, --json)");
    }
    return stability_diagram(*a.diagram, a.scan, a.out, a.json);
  }
  if (a.scenario.empty())
    throw InputError("scenario: missing: give a scenario file (or --diagram)");
  if (io::is_orbit_scenario(a.scenario)) {
    if (a.axis || a.omega || a.scan_omega || a.scan || a.out) {
      throw InputError(
          "--axis, --omega, --scan-omega, --scan, --out: not available on an orbit scenario (its "
          "initial state, or --equilibrium K, must be a relative equilibrium)");
    }
    return orbit_stability(a.scenario, a.json, a.equilibrium);
  }
  // Every option is checked before any work is done.
  if (a.scan && a.scan_omega) {
    throw InputError("--scan: give either --scan or --scan-omega, not both");
  }
  if (a.scan && !a.out) throw InputError("--scan: needs --out FILE for the CSV diagram");
  if (a.out && !a.scan && !a.scan_omega) {
    throw InputError("--out: needs --scan-omega or --scan (the diagram it holds)");
  }
  const std::optional<Range> omega_range =
      a.scan_omega ? std::optional(parse_range("--scan-omega", *a.scan_omega, false))
                   : std::nullopt;
  const std::optional<std::pair<Range, Range>> grid =
      a.scan ? std::optional(parse_grid(*a.scan)) : std::nullopt;
  const io::Scenario sc = io::load_scenario(a.scenario);
  if (a.axis || a.scan || a.scan_omega) {
    require_quadratic(sc.model, sc.source,
                      std::string(a.axis   ? "--axis"
                                  : a.scan ? "--scan"
                                           : "--scan-omega") +
                          " (spins about principal axes and their thresholds)");
  }
  const Chosen c = chosen_state(sc, a);
  if ((a.scan_omega || a.scan) && !c.axis) {
    throw InputError(
        std::string(a.scan ? "--scan" : "--scan-omega") +
        ": needs a spin about a principal axis: give --axis x|y|z (with M g r0 along it)");
  }
  // The diagram's file is created (and checked against the inputs) before any work.
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) file = std::make_unique<io::AtomicFile>(*a.out, sc.input_files);
  io::Json j = report(sc, c);
  if (a.equilibrium) j["equilibrium"] = *a.equilibrium;
  if (omega_range) j["scan"] = omega_scan(sc.model.quadratic(), *c.axis, *omega_range, file.get());
  if (grid) grid_scan(sc.model.quadratic(), *c.axis, a.omega.value_or(0.0), *grid, *file);
  if (a.out) j["csv"] = *a.out;
  j["model"] = model_json(sc.model);
  j["field"] = field_json(sc.model);
  if (a.json) {
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop stability " << sc.source << "\n";
  print_model(std::cout, sc.model);
  if (a.equilibrium) std::cout << "equilibrium " << *a.equilibrium << " of newtop equilibria\n";
  print_report(std::cout, j);
  if (omega_range) print_omega_scan(std::cout, j["scan"]);
  if (a.out) std::cout << "diagram written to " << *a.out << "\n";
  return kExitOk;
}

const RegisterCommand reg{Command{
    "stability",
    "Linear and energy-Casimir stability of an equilibrium or permanent rotation; diagrams",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<StabilityArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML); none with --diagram");
      sub.add_option("--axis", a->axis,
                     "analyse the spin about this principal axis (x, y or z), "
                     "pointing at the centre, instead of the initial state");
      sub.add_option("--omega", a->omega, "spin rate Omega about --axis (default 0)");
      sub.add_option("--equilibrium", a->equilibrium,
                     "analyse the K-th equilibrium listed by newtop equilibria (K = 1, 2, ...)");
      sub.add_option("--scan-omega", a->scan_omega, "W1:W2:N: stability along Omega (JSON, CSV)");
      sub.add_option("--scan", a->scan,
                     "P1=LO:HI:N,P2=LO:HI:M with P in omega, lambda, A, B, C: 2-D diagram to CSV");
      sub.add_option("--out", a->out, "CSV file for --scan-omega, --scan or --diagram");
      sub.add_option("--diagram", a->diagram,
                     "debra-delp: the DeBra-Delp diagram of a gravity-gradient satellite over "
                     "--scan k_R=LO:HI:N,k_Y=LO:HI:M (default -0.99:0.99:67 each)");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
