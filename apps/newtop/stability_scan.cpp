// Stability diagrams of `newtop stability` (--scan-omega, --scan).

#include "stability_scan.hpp"

#include <iomanip>
#include <memory>
#include <vector>

#include "newtop/analysis/stability_spin.hpp"
#include "summary.hpp"

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
  print_units_line(os);  // before the table, so that the table ends the output (as sweep's)
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
