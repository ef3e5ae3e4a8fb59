#include "newtop/io/analytic_json.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <variant>

#include "newtop/analysis/brun_level.hpp"
#include "newtop/analysis/brun_prym.hpp"
#include "newtop/analysis/brun_prym_inversion.hpp"
#include "newtop/analysis/brun_prym_periods.hpp"
#include "newtop/analysis/lagrange_attitude.hpp"
#include "newtop/model/attitude.hpp"

namespace newtop::io {
namespace {

Json nullable(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

/// The Lagrange top's Euler angles (φ, θ, ψ) and its symmetry axis e3 in the fixed frame N (z along
/// e: R e3 = q e3) at the times; null where γ3 = ±1 leaves φ and ψ undefined.
Json euler_angles_json(const LagrangeCase& l, const std::vector<double>& times) {
  Json euler = Json::array();
  for (double t : times) {
    const Vec3 angles = lagrange_euler_angles(l, t);
    const Vec3 axis = from_euler_313(angles) * Vec3::UnitZ();
    const bool finite = angles.allFinite() && axis.allFinite();
    euler.push_back({{"t", t},
                     {"phi", finite ? Json(angles[0]) : Json(nullptr)},
                     {"theta", finite ? Json(angles[1]) : Json(nullptr)},
                     {"psi", finite ? Json(angles[2]) : Json(nullptr)},
                     {"axis", finite ? to_json(axis) : Json(nullptr)}});
  }
  return euler;
}

Json complex_json(std::complex<double> z) { return {z.real(), z.imag()}; }

/// The level's constants: e_i, the roots of N, h, c, f, λ.
Json level_json(const BrunCurve& k) {
  return {{"e", k.e}, {"nu", k.nu}, {"h", k.h}, {"c", k.c}, {"f", k.f}, {"lambda", k.lambda_}};
}

void add_brun_details(Json& j, const BrunCase& b, const std::vector<double>& times) {
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
          ? Json{{"p", b.resonance->p}, {"q", b.resonance->q}, {"defect", b.resonance->defect}}
          : Json(nullptr);
  Json u = Json::array();
  for (double t : times) {
    const auto phi = brun_angles_at(b, t);
    u.push_back({{"t", t}, {"u1", brun_u_at(k, 0, phi[0])}, {"u2", brun_u_at(k, 1, phi[1])}});
  }
  j["u"] = u;
}

void add_brun_prym_details(Json& j, const BrunPrymSolution& s) {
  const BrunCurve& k = s.curve;
  const State& x0 = s.initial;
  const BrunPrymCheck check = brun_prym_check(s);
  Json points = Json::array();
  for (const BrunPrymPoint& p : check.divisor) {
    points.push_back(
        {{"u", complex_json(p.u)}, {"v", complex_json(p.v)}, {"xi", complex_json(p.xi)}});
  }
  const double round_trip = check.round_trip_error;
  const BrunPrymRate& rate = check.rate;
  const BrunPrymFrequencies& fr = s.torus;
  const auto& w = fr.frequency;
  const Json resonance =
      fr.resonance
          ? Json{{"p", fr.resonance->p}, {"q", fr.resonance->q}, {"defect", fr.resonance->defect}}
          : Json(nullptr);
  const Json torus = {
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

}  // namespace

Json state_json(const Body& b, const State& s) {
  return {{"omega", to_json(omega(b, s))}, {"gamma", to_json(s.gamma)}};
}

/// ξ² = N(u) + 2√λ f v, with the coefficients of D = N² − 4λf² P and its roots; null when the
/// level has no such curve (equal moments).
Json brun_spectral_json(const QuadraticModel& model, const State& x0) {
  BrunCurve k;
  try {
    k = brun_level(model, x0);
  } catch (const InputError&) {
    return nullptr;
  }
  const BrunSpectralCurve g = brun_spectral_curve(k);
  Json roots = Json::array();
  for (const auto& r : g.branch_point) roots.push_back({r.real(), r.imag()});
  Json j = level_json(k);
  j["discriminant"] = g.discriminant;
  j["discriminant_roots"] = roots;
  return j;
}

/// The closed form on --dense N equally spaced times over the samples' span (analytic_curve).
Json curve_json(const Body& b, const AnalyticSolution& sol, const std::vector<double>& times,
                int n) {
  const AnalyticCurve c = analytic_curve(sol, times.front(), times.back(), n);
  Json om = Json::array(), ga = Json::array();
  for (const State& x : c.state) {
    om.push_back(to_json(omega(b, x)));
    ga.push_back(to_json(x.gamma));
  }
  Json j{{"t", c.t}, {"omega", om}, {"gamma", ga}};
  if (const auto* l = std::get_if<LagrangeCase>(&sol))
    j["euler_angles"] = euler_angles_json(*l, c.t);
  return j;
}

void add_case_details(Json& j, const AnalyticSolution& sol, const std::vector<double>& times) {
  j["period"] = nullptr;
  j["nutation_period"] = nullptr;
  j["turning_points"] = Json::array();
  if (const auto* e = std::get_if<EulerPoinsot>(&sol)) {
    j["period"] = nullable(e->period);
    j["modulus"] = e->modulus;
  } else if (const auto* p = std::get_if<Pendulum>(&sol)) {
    j["period"] = nullable(p->period);
    j["kind"] = to_string(p->kind);
    j["closed_form"] = p->closed_form;
    j["turning_points"] = p->turning_points;
  } else if (const auto* l = std::get_if<LagrangeCase>(&sol)) {
    j["nutation_period"] = nullable(l->nutation_period);
    j["turning_points"] = {std::min(l->u1, l->u2), std::max(l->u1, l->u2)};
    const LagrangeQuartic& q = l->quartic;
    j["E"] = q.E, j["a"] = q.a, j["a1"] = q.a1, j["b"] = q.b, j["c"] = q.c, j["r"] = q.r;
    j["quartic_roots"] = l->real_roots;
    Json g = Json::array();
    for (double t : times) g.push_back({{"t", t}, {"gamma3", lagrange_gamma3(*l, t)[0]}});
    j["gamma3"] = g;
    j["euler_angles"] = euler_angles_json(*l, times);
  } else if (const auto* b = std::get_if<BrunCase>(&sol)) {
    add_brun_details(j, *b, times);
  } else if (const auto* bp = std::get_if<BrunPrymSolution>(&sol)) {
    add_brun_prym_details(j, *bp);
  }
}

Json samples_json(const Body& b, const AnalyticComparison& r) {
  Json samples = Json::array();
  for (std::size_t k = 0; k < r.times.size(); ++k) {
    Json s{{"t", r.times[k]}, {"analytic", state_json(b, r.analytic[k])}, {"numeric", nullptr}};
    if (const auto& x = r.numeric[k]) s["numeric"] = state_json(b, *x);
    samples.push_back(s);
  }
  return samples;
}

}  // namespace newtop::io
