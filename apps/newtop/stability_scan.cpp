// Stability diagrams of `newtop stability` (--scan-omega, --scan).

#include "stability_scan.hpp"

#include <iomanip>
#include <memory>
#include <sstream>
#include <vector>

#include "newtop/analysis/stability_spin.hpp"

namespace newtop::app {
namespace {

/// One grid point of --scan: the model with the parameters replaced, or nullopt if unphysical.
std::optional<Spectrum> grid_point(const QuadraticModel& base, int axis, double omega0,
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
    const QuadraticModel m{Body::from_principal(I, base.body.mass(), base.body.center_of_mass()),
                           QuadraticField::coulomb(base.field.g, lambda)};
    return spin_stability(m, axis, w);
  } catch (const InputError&) {
    return std::nullopt;  // e.g. the triangle inequality fails at this point of the grid
  }
}

}  // namespace

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
      r.n < 1 || r.n > kMaxScanPoints || !std::isfinite(r.lo) || !std::isfinite(r.hi)) {
    throw InputError(flag + ": expected " + (named ? "NAME=LO:HI:N" : "LO:HI:N") +
                     " (two finite numbers and a count from 1 to " +
                     std::to_string(kMaxScanPoints) + "), found '" + text + "'");
  }
  if (named && r.name != "omega" && r.name != "lambda" && r.name != "A" && r.name != "B" &&
      r.name != "C") {
    throw InputError(flag + ": expected a parameter omega, lambda, A, B or C, found '" + r.name +
                     "'");
  }
  return r;
}

std::pair<Range, Range> parse_grid(const std::string& spec) {
  const auto comma = spec.find(',');
  if (comma == std::string::npos) {
    throw InputError("--scan: expected P1=LO:HI:N,P2=LO:HI:M, found '" + spec + "'");
  }
  const Range r1 = parse_range("--scan", spec.substr(0, comma), true);
  const Range r2 = parse_range("--scan", spec.substr(comma + 1), true);
  if (static_cast<long long>(r1.n) * r2.n > kMaxGridPoints) {
    throw InputError("--scan: expected at most " + std::to_string(kMaxGridPoints) +
                     " grid points N*M, found " + std::to_string(r1.n) + "*" +
                     std::to_string(r2.n));
  }
  return {r1, r2};
}

io::Json omega_scan(const QuadraticModel& model, int axis, const Range& r, io::AtomicFile* file) {
  const auto points = scan_omega(model, axis, r.lo, r.hi, r.n);
  if (file) {
    file->stream() << "omega,max_real_part,linearly_stable,energy_casimir_stable\n";
  }
  io::Json list = io::Json::array();
  for (const auto& p : points) {
    list.push_back({{"omega", p.omega},
                    {"max_real_part", p.max_real_part},
                    {"linearly_stable", p.linearly_stable},
                    {"lyapunov_stable", optional_json(p.lyapunov_stable)}});
    if (file) {
      // energy_casimir_stable = 1: the energy–Casimir test proves Lyapunov stability
      // (lyapunov_stable true); 0 with linearly_stable = 1: inconclusive.
      file->stream() << format_number(p.omega) << ',' << format_number(p.max_real_part) << ','
                     << (p.linearly_stable ? 1 : 0) << ','
                     << (p.lyapunov_stable.value_or(false) ? 1 : 0) << '\n';
    }
  }
  if (file) file->commit();
  return list;
}

void grid_scan(const QuadraticModel& model, int axis, double omega0,
               const std::pair<Range, Range>& grid, io::AtomicFile& file) {
  const auto& [r1, r2] = grid;
  file.stream() << r1.name << ',' << r2.name << ",max_real_part,verdict\n";
  for (int i = 0; i < r1.n; ++i) {
    for (int k = 0; k < r2.n; ++k) {
      const auto s = grid_point(model, axis, omega0, {{r1.name, r1.at(i)}, {r2.name, r2.at(k)}});
      file.stream() << format_number(r1.at(i)) << ',' << format_number(r2.at(k)) << ','
                    << (s ? format_number(s->max_real_part) : "nan") << ','
                    << (s ? (s->linearly_stable ? "stable" : "unstable") : "nonphysical") << '\n';
    }
  }
  file.commit();
}

void print_omega_scan(std::ostream& os, const io::Json& scan) {
  os << "Omega                    max real part            linear     Lyapunov\n";
  for (const auto& p : scan) {
    os << std::left << std::setw(25) << format_number(p["omega"].get<double>()) << std::setw(25)
       << format_number(p["max_real_part"].get<double>()) << std::setw(11)
       << (p["linearly_stable"].get<bool>() ? "stable" : "unstable")
       << verdict_text(optional_bool(p["lyapunov_stable"])) << "\n";
  }
}

std::string verdict_text(const std::optional<bool>& v) {
  return v ? (*v ? "stable" : "unstable") : "inconclusive";
}

std::optional<bool> optional_bool(const io::Json& v) {
  return v.is_null() ? std::nullopt : std::optional<bool>(v.get<bool>());
}

io::Json optional_json(const std::optional<bool>& v) {
  return v ? io::Json(*v) : io::Json(nullptr);
}

io::Json optional_json(const std::optional<double>& v) {
  return v ? io::Json(*v) : io::Json(nullptr);
}

}  // namespace newtop::app
