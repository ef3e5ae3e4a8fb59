#include "analytic_brun.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <iostream>
#include <numbers>

#include "newtop/analysis/brun_level.hpp"
#include "newtop/analysis/brun_prym.hpp"
#include "newtop/analysis/brun_prym_periods.hpp"
#include "newtop/io/output.hpp"

namespace newtop::app {
namespace {

io::Json complex_json(std::complex<double> z) { return {z.real(), z.imag()}; }

/// The level's constants: e_i, the roots of N, h, c, f, λ.
io::Json level_json(const BrunCurve& k) {
  return {{"e", k.e}, {"nu", k.nu}, {"h", k.h}, {"c", k.c}, {"f", k.f}, {"lambda", k.lambda_}};
}

}  // namespace

void add_brun_details(io::Json& j, const BrunCase& b, const std::vector<double>& times) {
  const BrunCurve& k = b.curve;
  std::vector<double> branch(k.root.begin(), k.root.end());
  std::sort(branch.begin(), branch.end());
  j["curve"] = level_json(k);
  j["curve"]["coefficients"] = k.coefficient;
  j["curve"]["branch_points"] = branch;
  j["u_ranges"] = {{k.root[k.lower[0]], k.root[k.upper[0]]},
                   {k.root[k.lower[1]], k.root[k.upper[1]]}};
  j["frequencies"] = b.frequency;
  j["periods"] = {2 * std::numbers::pi / b.frequency[0], 2 * std::numbers::pi / b.frequency[1]};
  j["rotation_number"] = b.frequency[0] / b.frequency[1];
  j["period_matrix"] = b.period;
  j["sign_flips"] = b.flips;
  j["resonant"] = b.resonance.has_value();
  j["resonance"] =
      b.resonance
          ? io::Json{{"p", b.resonance->p}, {"q", b.resonance->q}, {"defect", b.resonance->defect}}
          : io::Json(nullptr);
  io::Json u = io::Json::array();
  for (double t : times) {
    const auto phi = brun_angles_at(b, t);
    u.push_back({{"t", t}, {"u1", brun_u_at(k, 0, phi[0])}, {"u2", brun_u_at(k, 1, phi[1])}});
  }
  j["u"] = u;
}

/// ξ² = N(u) + 2√λ f v, with the coefficients of D = N² − 4λf² P and its roots; null when the
/// level has no such curve (equal moments).
io::Json brun_spectral_json(const QuadraticModel& model, const State& x0) {
  BrunCurve k;
  try {
    k = brun_level(model, x0);
  } catch (const InputError&) {
    return nullptr;
  }
  const BrunSpectralCurve g = brun_spectral_curve(k);
  io::Json roots = io::Json::array();
  for (const auto& r : g.branch_point) roots.push_back({r.real(), r.imag()});
  io::Json j = level_json(k);
  j["discriminant"] = g.discriminant;
  j["discriminant_roots"] = roots;
  return j;
}

void add_brun_prym_details(io::Json& j, const BrunPrymSolution& s) {
  const BrunCurve& k = s.curve;
  const State& x0 = s.initial;
  const BrunPrymDivisor d = brun_prym_divisor(k, x0);
  io::Json points = io::Json::array();
  for (const BrunPrymPoint& p : d) {
    points.push_back(
        {{"u", complex_json(p.u)}, {"v", complex_json(p.v)}, {"xi", complex_json(p.xi)}});
  }
  const State back = brun_prym_state(k, d);
  const double round_trip = std::max((back.m - x0.m).cwiseAbs().maxCoeff(),
                                     (back.gamma - x0.gamma).cwiseAbs().maxCoeff());
  const BrunPrymRate rate = brun_prym_rate(k, x0, rhs(s.model, x0));
  const BrunPrymFrequencies& fr = s.torus;
  const auto& w = fr.frequency;
  const io::Json resonance = fr.resonance ? io::Json{{"p", fr.resonance->p},
                                                     {"q", fr.resonance->q},
                                                     {"defect", fr.resonance->defect}}
                                          : io::Json(nullptr);
  const io::Json torus = {
      {"frequencies", w},
      {"periods", {2 * std::numbers::pi / std::abs(w[0]), 2 * std::numbers::pi / std::abs(w[1])}},
      {"rotation_number", w[0] / w[1]},
      {"resonant", fr.resonance.has_value()},
      {"resonance", resonance},
      {"torus_periods", fr.torus_period},
      {"torus_index", fr.index},
      {"velocity_c", {complex_json(fr.velocity_c[0]), complex_json(fr.velocity_c[1])}}};
  j["curve"] = level_json(k);
  j["spectral_curve"] = brun_spectral_json(s.model, x0);
  j["prym"] = {{"divisor", points},
               {"torus", torus},
               {"round_trip_error", round_trip},
               {"velocity", {complex_json(s.velocity_h[0]), complex_json(s.velocity_h[1])}},
               {"rate_at_start", {complex_json(rate.rate[0]), complex_json(rate.rate[1])}},
               {"table_nodes", s.table.size()}};
  for (const char* key : {"frequencies", "periods", "rotation_number", "resonant", "resonance"}) {
    j[key] = torus[key];
  }
}

void print_brun_prym(const io::Json& prym) {
  if (prym.is_null()) return;
  std::cout << "prym      the motion is linear on the Prym of the spectral curve through three "
               "points of it:\n";
  for (const auto& p : prym["divisor"]) std::cout << "  u = " << p["u"].dump() << "\n";
  std::cout << "  state -> points -> state: error " << format_number(prym["round_trip_error"])
            << "\n  rates of the Abel-Prym sums at the start " << prym["rate_at_start"].dump()
            << " (law " << prym["velocity"].dump() << ")\n";
  std::cout << "  the state at time t: t reduced modulo the torus periods "
            << prym["torus"]["torus_periods"].dump() << ", the Abel-Prym map inverted from "
            << prym["table_nodes"].dump() << " nodes over one cell\n";
}

}  // namespace newtop::app
