// newtop analytic SCENARIO.toml: detect the integrable case, evaluate its closed-form or quadrature
// solution and compare it with a high-accuracy numerical integration (rkf78).

#include "newtop/analysis/analytic.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <variant>

#include "command.hpp"
#include "newtop/analysis/analytic_comparison.hpp"
#include "newtop/integrate/run.hpp"
#include "newtop/io/analytic_json.hpp"
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
  return {io::samples_json(sc.model.body(), r), r.max_abs_error, r.reference, r.compared,
          r.seconds_per_sample};
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
      j["spectral_curve"] = io::brun_spectral_json(sc.model.quadratic(), sc.initial);
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
  io::add_case_details(j, sol, times);
  const Comparison c = compare(sc, sol, times);
  j["span_source"] = source;
  j["samples"] = c.samples;
  j["max_abs_error"] = c.max_err ? io::Json(*c.max_err) : io::Json(nullptr);
  j["seconds_per_sample"] = times.empty() ? io::Json(nullptr) : io::Json(c.seconds_per_sample);
  if (a.curve && times.empty()) {
    throw InputError(
        "--dense: expected a time span to draw over, found none (give --t-end or --times)");
  }
  if (a.curve) j["dense"] = io::curve_json(sc.model.body(), sol, times, *a.curve);
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

const RegisterCommand reg_analytic{Command{
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
