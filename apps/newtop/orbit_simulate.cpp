// newtop simulate / integrals on an orbit scenario: the (m, γ, n) equations integrated in time on
// a circular orbit and in the true anomaly on an elliptic one; the Jacobi integral and the
// Casimirs reported with their drift.

#include <cmath>
#include <iostream>
#include <memory>

#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "orbit_commands.hpp"
#include "orbit_summary.hpp"

namespace newtop::app {
namespace {

struct Tracker {
  OrbitValues initial, max_drift;
  double max_geometric = 0.0;  ///< max |γ·γ − γ0·γ0|, the geometric integral of docs/model.md §5
  void observe(const OrbitValues& v) {
    max_geometric =
        std::max(max_geometric, std::abs(v.casimirs.gamma_gamma - initial.casimirs.gamma_gamma));
    max_drift.integral = std::max(max_drift.integral, std::abs(v.integral - initial.integral));
    max_drift.casimir = std::max(max_drift.casimir, v.casimir);
  }
};

}  // namespace

MethodSettings orbit_method(const io::OrbitScenario& sc, const std::optional<std::string>& method,
                            std::optional<double> cli_step, std::optional<double> cli_tol) {
  const auto& f = sc.integrate;
  const std::optional<double> step = cli_step ? cli_step : (cli_tol ? std::nullopt : f.step);
  const std::optional<double> tol = cli_tol ? cli_tol : (cli_step ? std::nullopt : f.tol);
  MethodSettings m;
  m.name = method ? *method
           : cli_step || cli_tol
               ? std::string(cli_step ? kDefaultFixedMethod : kOrbitAdaptiveMethod)
           : f.method ? *f.method
                      : std::string(step ? kDefaultFixedMethod : kOrbitAdaptiveMethod);
  if (m.name == "rkf78") {
    if (!tol) throw InputError(sc.source + ": tol: method rkf78 needs --tol or [integrate] tol");
    m.abs_tol = m.rel_tol = *tol;
  } else {
    if (!step) {
      throw InputError(sc.source + ": step: method " + m.name +
                       " needs --step or [integrate] step");
    }
    m.step = *step;
  }
  validate_orbit_method(m);
  return m;
}

double orbit_t_end(const io::OrbitScenario& sc, std::optional<double> cli_t_end) {
  const std::optional<double> t_end = cli_t_end ? cli_t_end : sc.integrate.t_end;
  if (!t_end) throw InputError(sc.source + ": t_end: missing: give --t-end or [integrate] t_end");
  if (!std::isfinite(*t_end) || !(*t_end > sc.integrate.t0)) {
    throw InputError("t_end: expected a finite time > t0 = " + format_number(sc.integrate.t0) +
                     ", found " + format_number(*t_end));
  }
  return *t_end;
}

int orbit_simulate(const std::string& path, const OrbitSimulateArgs& a) {
  const io::OrbitScenario sc = io::load_orbit_scenario(path);
  const MethodSettings method = orbit_method(sc, a.method, a.step, a.tol);
  const std::optional<double> t_end = orbit_t_end(sc, a.t_end);
  const std::int64_t every = a.every.value_or(sc.output.every);
  if (every < 1)
    throw InputError("--every: expected an integer >= 1, found " + std::to_string(every));
  const std::optional<std::string> out_path = a.out ? a.out : sc.output.file;
  const double t0 = sc.integrate.t0;
  const std::int64_t max_steps = sc.integrate.max_steps.value_or(100'000'000);

  std::unique_ptr<io::AtomicFile> file;
  if (out_path) {
    file = std::make_unique<io::AtomicFile>(*out_path);
    file->stream() << orbit_csv_header(sc) << '\n';
  }
  Tracker tr{orbit_values(sc, sc.initial, start_variable(sc)), {}};
  std::int64_t count = 0;
  double last = std::nan("");
  // The observer's variable is t (circular) or ν (elliptic); rows carry the time.
  auto time_of = [&](double x) { return orbit_time(sc, x, t0); };
  auto observer = [&](double x, const OrbitState& s) {
    tr.observe(orbit_values(sc, s, x));
    if (file && count % every == 0) {
      file->stream() << orbit_csv_row(sc, s, x) << '\n';
      last = x;
    }
    ++count;
  };
  OrbitOutcome out;
  if (const auto* c = std::get_if<CircularOrbit>(&sc.orbit)) {
    out = run_orbit_method(method, CircularOrbitModel(sc.body, *c), sc.initial, t0, *t_end,
                           max_steps, observer);
  } else {
    const auto& e = std::get<EllipticOrbit>(sc.orbit);
    out = run_orbit_method(method, EllipticOrbitModel(sc.body, e), sc.initial, e.true_anomaly0,
                           true_anomaly_at(e, *t_end - t0), max_steps, observer);
  }
  if (file && last != out.t) file->stream() << orbit_csv_row(sc, out.state, out.t) << '\n';
  if (file) file->commit();
  const OrbitRunReport rep{sc,           method,
                           out,          time_of(out.t),
                           tr.initial,   orbit_values(sc, out.state, out.t),
                           tr.max_drift, tr.max_geometric,
                           out_path};
  if (a.json) {
    std::cout << orbit_simulation_json(rep).dump(2) << '\n';
  } else {
    print_orbit_simulation(std::cout, rep);
  }
  return out.status == Status::finished ? 0 : 3;
}

int orbit_integrals(const std::string& path, bool json) {
  const io::OrbitScenario sc = io::load_orbit_scenario(path);
  const OrbitValues v = orbit_values(sc, sc.initial, start_variable(sc));
  io::Json j;
  j["integrals"] = orbit_values_json(sc, v);
  j["conserved"] = sc.circular()
                       ? io::Json::array({"jacobi", "gamma_gamma", "normal_normal", "gamma_normal"})
                       : io::Json::array({"gamma_gamma", "normal_normal", "gamma_normal"});
  j["model"] = orbit_model_json(sc);
  if (json) {
    std::cout << j.dump(2) << '\n';
    return 0;
  }
  std::cout << "newtop integrals " << sc.source << "\n";
  print_orbit_model(std::cout, sc);
  std::cout.precision(17);
  for (const auto& [k, x] : j["integrals"].items()) std::cout << k << "  " << x.dump() << "\n";
  std::cout << "conserved: " << j["conserved"].dump() << "\n";
  return 0;
}

}  // namespace newtop::app
