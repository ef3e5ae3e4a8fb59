// newtop analytic SCENARIO.toml: detect the integrable case, evaluate its closed-form or quadrature
// solution and compare it with a high-accuracy numerical integration (rkf78).

// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "newtop/analysis/analytic.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <type_traits>
#include <variant>

#include "analytic_brun.hpp"
#include "command.hpp"
#include "newtop/analysis/analytic_comparison.hpp"
#include "newtop/analysis/lagrange_attitude.hpp"
#include "newtop/integrate/run.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "summary.hpp"
#include "times_option.hpp"

namespace newtop::app {
namespace {

constexpr double kReferenceTol = kAnalyticReferenceTol;
constexpr int kDefaultSamples = 20;

struct AnalyticArgs {
  std::string scenario;
  std::optional<double> t_end;
  std::optional<int> samples;
  std::optional<int> curve;
  std::optional<std::string> times;
  bool json = false;
};

/// The sample times and where their span came from: --times; or N + 1 equally spaced times in
/// [0, T] with T from --t-end, [integrate] t_end or, without either, one period of the solution.
/// Empty when there is no span at all (no t_end and no period).
std::vector<double> sample_times(const AnalyticArgs& a, const io::Scenario& sc,
                                 std::optional<double> period, std::string& source) {
  if (a.times) {
    source = "--times";
    std::vector<double> t = parse_times("--times", *a.times);
    std::sort(t.begin(), t.end());
    return t;
  }
  std::optional<double> t_end = a.t_end ? a.t_end : sc.integrate.t_end;
  source = a.t_end ? "--t-end" : "[integrate] t_end";
  if (!t_end) {
    t_end = period;
    source = "one period";
  }
  if (!t_end) {
    source = "none";
    return {};
  }
  if (!(std::isfinite(*t_end) && *t_end > 0)) {
    throw InputError(source + ": expected a time > 0, found " + format_number(*t_end));
  }
  const int n = a.samples.value_or(kDefaultSamples);
  if (n < 1) throw InputError("--samples: expected an integer >= 1, found " + std::to_string(n));
  std::vector<double> t;
  for (int i = 0; i <= n; ++i) t.push_back(i == n ? *t_end : *t_end * i / n);
  return t;
}

io::Json state_json(const Body& b, const State& s) {
  return {{"omega", io::to_json(omega(b, s))}, {"gamma", io::to_json(s.gamma)}};
}

io::Json nullable(double x) { return std::isfinite(x) ? io::Json(x) : io::Json(nullptr); }

/// The Lagrange top's Euler angles (φ, θ, ψ) and its symmetry axis e3 in the fixed frame N (z along
/// e: R e3 = q e3) at the times; null where γ3 = ±1 leaves φ and ψ undefined.
io::Json euler_angles_json(const LagrangeCase& l, const std::vector<double>& times) {
  io::Json euler = io::Json::array();
  for (double t : times) {
    const Vec3 angles = lagrange_euler_angles(l, t);
    const Vec3 axis = from_euler_313(angles) * Vec3::UnitZ();
    const bool finite = angles.allFinite() && axis.allFinite();
    euler.push_back({{"t", t},
                     {"phi", finite ? io::Json(angles[0]) : io::Json(nullptr)},
                     {"theta", finite ? io::Json(angles[1]) : io::Json(nullptr)},
                     {"psi", finite ? io::Json(angles[2]) : io::Json(nullptr)},
                     {"axis", finite ? io::to_json(axis) : io::Json(nullptr)}});
  }
  return euler;
}

/// The closed form on --dense N equally spaced times over the samples' span (analytic_curve).
io::Json curve_json(const Body& b, const AnalyticSolution& sol, const std::vector<double>& times,
                    int n) {
  const AnalyticCurve c = analytic_curve(sol, times.front(), times.back(), n);
  io::Json om = io::Json::array(), ga = io::Json::array();
  for (const State& x : c.state) {
    om.push_back(io::to_json(omega(b, x)));
    ga.push_back(io::to_json(x.gamma));
  }
  io::Json j{{"t", c.t}, {"omega", om}, {"gamma", ga}};
  if (const auto* l = std::get_if<LagrangeCase>(&sol))
    j["euler_angles"] = euler_angles_json(*l, c.t);
  return j;
}

void add_case_details(io::Json& j, const AnalyticSolution& sol, const std::vector<double>& times) {
  j["period"] = nullptr;
  j["nutation_period"] = nullptr;
  j["turning_points"] = io::Json::array();
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
    io::Json g = io::Json::array();
    for (double t : times) g.push_back({{"t", t}, {"gamma3", lagrange_gamma3(*l, t)[0]}});
    j["gamma3"] = g;
    j["euler_angles"] = euler_angles_json(*l, times);
  } else if (const auto* b = std::get_if<BrunCase>(&sol)) {
    add_brun_details(j, *b, times);
  } else if (const auto* bp = std::get_if<BrunPrymSolution>(&sol)) {
    add_brun_prym_details(j, *bp);
  }
}

/// The comparison of the library (compare_analytic) as JSON: the samples, analytic beside numeric
/// ("numeric": null where the reference did not reach the time).
struct Comparison {
  io::Json samples = io::Json::array();
  std::optional<double> max_err;
  Outcome reference;
  std::int64_t compared = 0;
  double seconds_per_sample = 0;  ///< wall time of one analytic state, averaged
};

Comparison compare(const io::Scenario& sc, const AnalyticSolution& sol,
                   const std::vector<double>& times) {
  IntegrateOptions opt;
  if (sc.integrate.max_steps) opt.max_steps = *sc.integrate.max_steps;
  const AnalyticComparison r = compare_analytic(sc.model.quadratic(), sc.initial, sol, times, opt);
  Comparison c{io::Json::array(), r.max_abs_error, r.reference, r.compared, r.seconds_per_sample};
  const Body& b = sc.model.body();
  for (std::size_t k = 0; k < r.times.size(); ++k) {
    io::Json s{{"t", r.times[k]}, {"analytic", state_json(b, r.analytic[k])}, {"numeric", nullptr}};
    if (const auto& x = r.numeric[k]) s["numeric"] = state_json(b, *x);
    c.samples.push_back(s);
  }
  return c;
}

void print_summary(const io::Scenario& sc, const AnalyticDetection& det, const io::Json& j,
                   const Comparison& c, std::size_t n_times) {
  std::cout << "newtop analytic " << sc.source << "\ncase      " << to_string(det.kind) << "\n"
            << "          " << det.reason << "\n";
  for (const char* key :
       {"kind", "period", "nutation_period", "turning_points", "E", "a", "a1", "b", "c", "r",
        "quartic_roots", "u_ranges", "frequencies", "rotation_number", "resonance"}) {
    if (j.contains(key) && !j[key].is_null()) {
      std::cout << "  " << key << " = " << j[key].dump() << "\n";
    }
  }
  if (j.contains("prym")) print_brun_prym(without_negative_zeros(j["prym"]));
  if (n_times == 0) {
    std::cout << "samples   none: no time span (no t_end, and the solution has no period); give "
                 "--t-end or --times to compare with a numerical run\n";
    return;
  }
  std::cout << "samples   " << n_times << " over " << j["span_source"].get<std::string>()
            << " (analytic vs rkf78 at tol " << format_number(kReferenceTol) << ")\n";
  if (c.reference.status != Status::finished) {
    std::cout << "reference FAILED: " << to_string(c.reference.status)
              << " at t = " << format_number(c.reference.t) << " after " << c.reference.steps
              << " steps; " << n_times - static_cast<std::size_t>(c.compared)
              << " samples after it are not compared\n";
  }
  std::cout << "analytic  " << format_number(c.seconds_per_sample) << " s per sample\n";
  std::cout << "max |analytic - numeric| (omega, gamma) = "
            << (c.max_err ? format_number(*c.max_err) : std::string("none compared")) << "\n";
}

int run(const AnalyticArgs& a) {
  const io::Scenario sc = io::load_scenario(a.scenario);
  require_quadratic(sc.model, sc.source, "newtop analytic (the closed forms of docs/model.md §5)");
  const AnalyticDetection det = detect_analytic_case(sc.model.quadratic(), sc.initial);
  io::Json j;
  j["case"] = to_string(det.kind);
  j["reason"] = det.reason;
  if (a.curve && !det.solved) {
    throw InputError("--dense: expected a solved case to draw, found case " +
                     std::string(to_string(det.kind)) + " (" + det.reason + ")");
  }
  if (!det.solved) {
    j["period"] = nullptr, j["nutation_period"] = nullptr;
    j["turning_points"] = io::Json::array(), j["samples"] = io::Json::array();
    j["max_abs_error"] = nullptr;
    if (det.kind == AnalyticKind::brun) {
      j["spectral_curve"] = brun_spectral_json(sc.model.quadratic(), sc.initial);
    }
    if (a.json) {
      j["field"] = field_json(sc.model);
      print_json(std::cout, j);
    } else {
      std::cout << "newtop analytic " << sc.source << "\ncase      " << to_string(det.kind)
                << "\n          " << det.reason << "\n";
    }
    return kExitOk;
  }
  const AnalyticSolution sol = analytic_solution(sc.model.quadratic(), sc.initial, det.kind);
  std::string source;
  const std::vector<double> times = sample_times(a, sc, solution_period(sol), source);
  add_case_details(j, sol, times);
  const Comparison c = compare(sc, sol, times);
  j["span_source"] = source;
  j["samples"] = c.samples;
  j["max_abs_error"] = c.max_err ? io::Json(*c.max_err) : io::Json(nullptr);
  j["seconds_per_sample"] = times.empty() ? io::Json(nullptr) : io::Json(c.seconds_per_sample);
  if (a.curve && times.empty()) {
    throw InputError(
        "--dense: expected a time span to draw over, found none (give --t-end or --times)");
  }
  if (a.curve) j["dense"] = curve_json(sc.model.body(), sol, times, *a.curve);
  const bool failed = !times.empty() && c.reference.status != Status::finished;
  if (!times.empty()) {
    j["reference"] = {{"method", "rkf78"},
                      {"tol", kReferenceTol},
                      {"outcome", std::string(to_string(c.reference.status))},
                      {"t", c.reference.t},
                      {"steps", c.reference.steps},
                      {"compared_samples", c.compared}};
  } else {
    j["reference"] = nullptr;
  }
  if (a.json) {
    j["field"] = field_json(sc.model);
    print_json(std::cout, j);
  } else {
    print_summary(sc, det, without_negative_zeros(j), c, times.size());
  }
  return failed ? kExitIncomplete : kExitOk;
}

const RegisterCommand reg{Command{
    "analytic",
    "Detect the integrable case (Euler-Poinsot, pendulum, Lagrange, Brun) and compare its "
    "analytic solution with the numerical motion",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<AnalyticArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      sub.add_option("--t-end", a->t_end, "last sample time (default: [integrate] t_end)");
      auto* n = sub.add_option("--samples", a->samples, "number of sample intervals (default 20)");
      auto* t = sub.add_option("--times", a->times, "comma-separated sample times");
      n->excludes(t);
      auto* curve = sub.add_option(
          "--dense", a->curve,
          "with --json: also the closed form alone at N equally spaced times over the samples' "
          "span (\"dense\"), for drawing");
      curve->needs(sub.add_flag("--json", a->json, "print one JSON object"));
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
