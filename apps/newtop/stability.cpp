// newtop stability SCENARIO.toml: linear and energy–Casimir stability of the scenario's initial
// state (an equilibrium or a permanent rotation) or of the spin --axis/--omega (spec §7–§9);
// stability diagrams along Ω (--scan-omega) or over two parameters (--scan).

#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "command.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct StabilityArgs {
  std::string scenario;
  std::optional<std::string> axis, scan_omega, scan, out;
  std::optional<double> omega;
  bool json = false;
};

struct Range {
  std::string name;
  double lo, hi;
  int n;
  double at(int k) const { return n == 1 ? lo : lo + (hi - lo) * k / (n - 1); }
};

/// "LO:HI:N" (optionally "NAME=LO:HI:N" when `named`).
Range parse_range(const std::string& flag, const std::string& text, bool named) {
  Range r{"omega", 0, 0, 0};
  std::string spec = text;
  if (named) {
    const auto eq = text.find('=');
    if (eq != std::string::npos) r.name = text.substr(0, eq);
    spec = eq == std::string::npos ? "" : text.substr(eq + 1);
  }
  std::istringstream is(spec);
  char c1 = 0, c2 = 0;
  std::string rest;
  if (!(is >> r.lo >> c1 >> r.hi >> c2 >> r.n) || c1 != ':' || c2 != ':' || (is >> rest) ||
      r.n < 1 || !std::isfinite(r.lo) || !std::isfinite(r.hi)) {
    throw InputError(flag + ": expected " + (named ? "NAME=LO:HI:N" : "LO:HI:N") +
                     " (two finite numbers and a count >= 1), found '" + text + "'");
  }
  if (named && r.name != "omega" && r.name != "lambda" && r.name != "A" && r.name != "B" &&
      r.name != "C") {
    throw InputError(flag + ": expected a parameter omega, lambda, A, B or C, found '" + r.name +
                     "'");
  }
  return r;
}

std::optional<int> parse_axis(const std::optional<std::string>& axis) {
  if (!axis) return std::nullopt;
  if (*axis == "x") return 0;
  if (*axis == "y") return 1;
  if (*axis == "z") return 2;
  throw InputError("--axis: expected x, y or z, found '" + *axis + "'");
}

/// The principal axis i with γ = e_i and ω ∥ e_i (or ω = 0), where the spin family about it is a
/// fixed point for every Ω (M g r0 along e_i).
std::optional<int> spin_axis_of(const Model& model, const State& s) {
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

std::string verdict_text(const std::optional<bool>& v) {
  return v ? (*v ? "stable" : "unstable") : "inconclusive";
}

io::Json optional_json(const std::optional<bool>& v) {
  return v ? io::Json(*v) : io::Json(nullptr);
}
io::Json optional_json(const std::optional<double>& v) {
  return v ? io::Json(*v) : io::Json(nullptr);
}

/// --scan-omega: the diagram along Ω, to CSV (--out) and JSON.
io::Json omega_scan(const Model& model, int axis, const Range& r,
                    const std::optional<std::string>& out) {
  const auto points = scan_omega(model, axis, r.lo, r.hi, r.n);
  std::unique_ptr<io::AtomicFile> file;
  if (out) {
    file = std::make_unique<io::AtomicFile>(*out);
    file->stream() << "omega,max_real_part,linearly_stable,lyapunov_stable\n";
  }
  io::Json list = io::Json::array();
  for (const auto& p : points) {
    list.push_back({{"omega", p.omega},
                    {"max_real_part", p.max_real_part},
                    {"linearly_stable", p.linearly_stable},
                    {"lyapunov_stable", optional_json(p.lyapunov_stable)}});
    if (file) {
      file->stream() << format_number(p.omega) << ',' << format_number(p.max_real_part) << ','
                     << (p.linearly_stable ? "true" : "false") << ','
                     << (p.lyapunov_stable ? (*p.lyapunov_stable ? "true" : "false") : "") << '\n';
    }
  }
  if (file) file->commit();
  return list;
}

/// One grid point of --scan: the model with the parameters replaced, or nullopt if unphysical.
std::optional<Spectrum> grid_point(const Model& base, int axis, double omega0,
                                   const std::vector<std::pair<std::string, double>>& values) {
  Vec3 I = base.body.inertia();
  double lambda = base.field.lambda_, w = omega0;
  for (const auto& [name, v] : values) {
    if (name == "omega") w = v;
    if (name == "lambda") lambda = v;
    if (name == "A") I.x() = v;
    if (name == "B") I.y() = v;
    if (name == "C") I.z() = v;
  }
  try {
    const Model m{Body::from_principal(I, base.body.mass(), base.body.center_of_mass()),
                  QuadraticField::coulomb(base.field.g, lambda)};
    return spin_stability(m, axis, w);
  } catch (const InputError&) {
    return std::nullopt;  // e.g. the triangle inequality fails at this point of the grid
  }
}

/// --scan P1=..,P2=..: the two-parameter diagram to CSV.
void grid_scan(const Model& model, int axis, double omega0, const std::string& spec,
               const std::string& out) {
  const auto comma = spec.find(',');
  if (comma == std::string::npos) {
    throw InputError("--scan: expected P1=LO:HI:N,P2=LO:HI:M, found '" + spec + "'");
  }
  const Range r1 = parse_range("--scan", spec.substr(0, comma), true);
  const Range r2 = parse_range("--scan", spec.substr(comma + 1), true);
  io::AtomicFile file(out);
  file.stream() << r1.name << ',' << r2.name << ",max_real_part,verdict\n";
  for (int i = 0; i < r1.n; ++i) {
    for (int k = 0; k < r2.n; ++k) {
      const auto s = grid_point(model, axis, omega0, {{r1.name, r1.at(i)}, {r2.name, r2.at(k)}});
      file.stream() << format_number(r1.at(i)) << ',' << format_number(r2.at(k)) << ','
                    << (s ? format_number(s->max_real_part) : "") << ','
                    << (s ? (s->linearly_stable ? "stable" : "unstable") : "nonphysical") << '\n';
    }
  }
  file.commit();
}

/// The state to analyse and the spin axis (if the state is a spin about a principal axis).
std::pair<State, std::optional<int>> chosen_state(const io::Scenario& sc, const StabilityArgs& a) {
  const std::optional<int> axis = parse_axis(a.axis);
  if (a.omega && !axis) throw InputError("--omega: needs --axis x|y|z to say which axis spins");
  const State s = axis ? principal_spin(sc.model.body, *axis, a.omega.value_or(0.0)) : sc.initial;
  const double res = fixed_point_residual(sc.model, s);
  if (!(res <= kFixedPointTolerance)) {
    throw InputError(std::string(axis ? "--axis " + *a.axis : sc.source + ": [initial]") +
                     ": expected an equilibrium or a permanent rotation (relative residual of d(m, "
                     "gamma)/dt <= " +
                     format_number(kFixedPointTolerance) + "), found residual " +
                     format_number(res) +
                     (axis ? " (M g r0 is not along the axis)"
                           : "; see newtop equilibria / rotations, or use --axis and --omega"));
  }
  return {s, axis ? axis : spin_axis_of(sc.model, s)};
}

io::Json report(const io::Scenario& sc, const State& s, std::optional<int> axis) {
  const Model& m = sc.model;
  const Spectrum sp = linear_stability(m, s);
  io::Json j;
  j["eigenvalues"] = io::Json::array();
  for (const auto& z : sp.eigenvalues) j["eigenvalues"].push_back({z.real(), z.imag()});
  j["max_real_part"] = sp.max_real_part;
  j["linearly_stable"] = sp.linearly_stable;
  j["lyapunov_stable"] = optional_json(sp.lyapunov_stable);
  const bool no_offset = m.body.mass() * m.field.g * m.body.center_of_mass().norm() == 0.0;
  j["threshold_omega_formula"] = optional_json(
      axis && no_offset ? beletsky_threshold(m.body, m.field.lambda_, *axis) : std::nullopt);
  j["threshold_omega_numeric"] =
      optional_json(axis ? numeric_threshold(m, *axis) : std::optional<double>{});
  j["axis"] = axis ? io::Json(std::string(1, "xyz"[*axis])) : io::Json(nullptr);
  j["axis_class"] = axis ? io::Json(to_string(axis_class(m.body, *axis))) : io::Json(nullptr);
  j["omega"] = io::to_json(omega(m.body, s));
  j["gamma"] = io::to_json(s.gamma);
  j["residual"] = fixed_point_residual(m, s);
  return j;
}

void print_report(std::ostream& os, const io::Json& j) {
  os << "state     omega = " << j["omega"].dump() << "  gamma = " << j["gamma"].dump()
     << "  (fixed-point residual " << format_number(j["residual"].get<double>()) << ")\n";
  os << "eigenvalues on the symplectic leaf:";
  for (const auto& z : j["eigenvalues"])
    os << "  " << z[0].get<double>() << (z[1].get<double>() < 0 ? "" : "+") << z[1].get<double>()
       << "i";
  os << "\nmax real part " << format_number(j["max_real_part"].get<double>())
     << "\nlinear (spectral) stability: "
     << (j["linearly_stable"].get<bool>() ? "stable" : "unstable")
     << "\nLyapunov (energy-Casimir): "
     << verdict_text(j["lyapunov_stable"].is_null()
                         ? std::nullopt
                         : std::optional<bool>(j["lyapunov_stable"].get<bool>()))
     << "\n";
  if (!j["axis"].is_null()) {
    os << "spin axis " << j["axis"].get<std::string>() << " (" << j["axis_class"].get<std::string>()
       << " moment); threshold Omega: formula " << j["threshold_omega_formula"].dump()
       << ", numeric " << j["threshold_omega_numeric"].dump() << "\n";
  }
}

int run(const StabilityArgs& a) {
  const io::Scenario sc = io::load_scenario(a.scenario);
  const auto [s, axis] = chosen_state(sc, a);
  io::Json j = report(sc, s, axis);
  if ((a.scan_omega || a.scan) && !axis) {
    throw InputError(
        std::string(a.scan ? "--scan" : "--scan-omega") +
        ": needs a spin about a principal axis: give --axis x|y|z (with M g r0 along it)");
  }
  if (a.scan && a.scan_omega)
    throw InputError("--scan: give either --scan or --scan-omega, not both");
  if (a.scan && !a.out) throw InputError("--scan: needs --out FILE for the CSV diagram");
  if (a.scan_omega) {
    j["scan"] =
        omega_scan(sc.model, *axis, parse_range("--scan-omega", *a.scan_omega, false), a.out);
  } else if (a.scan) {
    grid_scan(sc.model, *axis, a.omega.value_or(0.0), *a.scan, *a.out);
  }
  if (a.out) j["csv"] = *a.out;
  j["model"] = model_json(sc.model);
  if (a.json) {
    std::cout << j.dump(2) << '\n';
    return kExitOk;
  }
  std::cout << "newtop stability " << sc.source << "\n";
  print_model(std::cout, sc.model);
  print_report(std::cout, j);
  if (a.out) std::cout << "diagram written to " << *a.out << "\n";
  return kExitOk;
}

const RegisterCommand reg{Command{
    "stability",
    "Linear and energy-Casimir stability of an equilibrium or permanent rotation; diagrams",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<StabilityArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      sub.add_option("--axis", a->axis,
                     "analyse the spin about this principal axis (x, y or z), "
                     "pointing at the centre, instead of the initial state");
      sub.add_option("--omega", a->omega, "spin rate Omega about --axis (default 0)");
      sub.add_option("--scan-omega", a->scan_omega, "W1:W2:N: stability along Omega (JSON, CSV)");
      sub.add_option("--scan", a->scan,
                     "P1=LO:HI:N,P2=LO:HI:M with P in omega, lambda, A, B, C: 2-D diagram to CSV");
      sub.add_option("--out", a->out, "CSV file for --scan-omega or --scan");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
