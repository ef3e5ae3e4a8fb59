// The human summary of `newtop stability` (stability_text.hpp).

#include "newtop/io/stability_text.hpp"

#include <cmath>
#include <iomanip>

namespace newtop::io {
namespace {

/// "stable", "unstable" or "inconclusive" (null) for a Lyapunov verdict.
std::string verdict_text(const Json& v) {
  return v.is_null() ? "inconclusive" : (v.get<bool>() ? "stable" : "unstable");
}

/// A number, or `missing` when the JSON value is null (never "null" in a human summary).
std::string optional_text(const Json& v, const std::string& missing) {
  return v.is_null() ? missing : format_number(v.get<double>());
}

Vec3 vec(const Json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

std::string complex_text(const Json& z) {
  const double im = z[1].get<double>();
  return format_number(z[0].get<double>()) + (im < 0 ? "-" : "+") + format_number(std::abs(im)) +
         "i";
}

}  // namespace

void write_omega_scan_text(std::ostream& os, const Json& scan) {
  os << "Omega                    max real part            linear     Lyapunov\n";
  for (const auto& p : scan) {
    os << std::left << std::setw(25) << format_number(p["omega"].get<double>()) << std::setw(25)
       << format_number(p["max_real_part"].get<double>()) << std::setw(11)
       << (p["linearly_stable"].get<bool>() ? "stable" : "unstable")
       << verdict_text(p["lyapunov_stable"]) << "\n";
  }
}

void write_stability_text(std::ostream& os, const Json& j, const std::string& formula_note) {
  const Json& p = j["polish"];
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
     << "\nLyapunov (energy-Casimir): " << verdict_text(j["lyapunov_stable"]) << "\n";
  if (!j["axis"].is_null()) {
    os << "spin axis " << j["axis"].get<std::string>() << " (" << j["axis_class"].get<std::string>()
       << " moment); threshold Omega: formula "
       << optional_text(j["threshold_omega_formula"], formula_note) << ", numeric "
       << optional_text(j["threshold_omega_numeric"], "none (no unstable-to-stable change)")
       << "\n";
  }
}

}  // namespace newtop::io
