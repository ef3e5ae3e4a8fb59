// newtop analytic SCENARIO.toml: detect the integrable case, evaluate its closed-form or quadrature
// solution and compare it with a high-accuracy numerical integration (rkf78).

// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "newtop/analysis/analytic.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "command.hpp"
#include "newtop/integrate/methods.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::app {
namespace {

// Tolerance of the numerical reference: its global error (~1e-12 over a few periods) stays well
// below the 1e-10 at which the analytic solutions are validated.
constexpr double kReferenceTol = 1e-13;
constexpr int kDefaultSamples = 20;

struct AnalyticArgs {
  std::string scenario;
  std::optional<double> t_end;
  std::optional<int> samples;
  std::optional<std::string> times;
  bool json = false;
};

std::vector<double> sample_times(const AnalyticArgs& a, const io::Scenario& sc) {
  std::vector<double> t;
  if (a.times) {
    std::stringstream ss(*a.times);
    std::string item;
    while (std::getline(ss, item, ',')) {
      try {
        std::size_t used = 0;
        const double v = std::stod(item, &used);
        if (used != item.size() || !std::isfinite(v) || v < 0) throw std::invalid_argument("");
        t.push_back(v);
      } catch (const std::exception&) {
        throw InputError("--times: expected comma-separated times >= 0, found '" + item + "'");
      }
    }
    std::sort(t.begin(), t.end());
    return t;
  }
  const double t_end = a.t_end ? *a.t_end : io::resolve_t_end(sc, {});
  if (!(std::isfinite(t_end) && t_end > 0)) {
    throw InputError("--t-end: expected a time > 0, found " + format_number(t_end));
  }
  const int n = a.samples.value_or(kDefaultSamples);
  if (n < 1) throw InputError("--samples: expected an integer >= 1, found " + std::to_string(n));
  for (int i = 0; i <= n; ++i) t.push_back(t_end * i / n);
  return t;
}

io::Json state_json(const Body& b, const State& s) {
  return {{"omega", io::to_json(omega(b, s))}, {"gamma", io::to_json(s.gamma)}};
}

io::Json nullable(double x) { return std::isfinite(x) ? io::Json(x) : io::Json(nullptr); }

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
  }
}

int run(const AnalyticArgs& a) {
  const io::Scenario sc = io::load_scenario(a.scenario);
  const AnalyticDetection det = detect_analytic_case(sc.model, sc.initial);
  io::Json j;
  j["case"] = to_string(det.kind);
  j["reason"] = det.reason;
  const bool solved = det.kind != AnalyticKind::brun && det.kind != AnalyticKind::none;
  if (!solved) {
    j["period"] = nullptr, j["nutation_period"] = nullptr;
    j["turning_points"] = io::Json::array(), j["samples"] = io::Json::array();
    j["max_abs_error"] = nullptr;
    if (a.json) {
      std::cout << j.dump(2) << '\n';
    } else {
      std::cout << "newtop analytic " << sc.source << "\ncase      " << to_string(det.kind)
                << "\n          " << det.reason << "\n";
    }
    return kExitOk;
  }
  const std::vector<double> times = sample_times(a, sc);
  const AnalyticSolution sol = analytic_solution(sc.model, sc.initial, det.kind);
  add_case_details(j, sol, times);
  io::Json samples = io::Json::array();
  double max_err = 0.0, t_prev = 0.0;
  State x = sc.initial;
  for (double t : times) {
    Fehlberg78Stepper stepper(kReferenceTol, kReferenceTol);
    x = integrate(stepper, sc.model, x, t_prev, t, {}).state;
    t_prev = t;
    const State an = analytic_state(sol, t);
    const Body& b = sc.model.body;
    max_err = std::max({max_err, (omega(b, an) - omega(b, x)).cwiseAbs().maxCoeff(),
                        (an.gamma - x.gamma).cwiseAbs().maxCoeff()});
    samples.push_back({{"t", t}, {"analytic", state_json(b, an)}, {"numeric", state_json(b, x)}});
  }
  j["samples"] = samples;
  j["max_abs_error"] = max_err;
  if (a.json) {
    std::cout << j.dump(2) << '\n';
    return kExitOk;
  }
  std::cout << "newtop analytic " << sc.source << "\ncase      " << to_string(det.kind) << "\n"
            << "          " << det.reason << "\n";
  for (const char* key : {"kind", "period", "nutation_period", "turning_points", "E", "a", "a1",
                          "b", "c", "r", "quartic_roots"}) {
    if (j.contains(key) && !j[key].is_null()) {
      std::cout << "  " << key << " = " << j[key].dump() << "\n";
    }
  }
  std::cout << "samples   " << times.size() << " (analytic vs rkf78 at tol "
            << format_number(kReferenceTol)
            << ")\nmax |analytic - numeric| (omega, gamma) = " << format_number(max_err) << "\n";
  return kExitOk;
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
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
