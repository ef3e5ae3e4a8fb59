// newtop simulate / integrals on an orbit scenario: the (m, γ, n) equations integrated in time on
// a circular orbit and in the true anomaly on an elliptic one; the Jacobi integral and the
// Casimirs reported with their drift.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/orbit_settings.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "newtop/orbit/orbit_section.hpp"
#include "orbit_commands.hpp"
#include "orbit_summary.hpp"
#include "summary.hpp"
#include "times_option.hpp"

namespace newtop::app {

MethodSettings orbit_method(const io::OrbitScenario& sc, const std::optional<std::string>& method,
                            std::optional<double> cli_step, std::optional<double> cli_tol) {
  return io::resolve_method(sc, {method, cli_step, cli_tol, std::nullopt, std::nullopt});
}

double orbit_t_end(const io::OrbitScenario& sc, std::optional<double> cli_t_end) {
  return io::resolve_t_end(sc, {std::nullopt, std::nullopt, std::nullopt, cli_t_end, std::nullopt});
}

namespace {

/// The rows of an orbit run: every N-th step, or the output times (in t; ν_k = ν(t_k) on an
/// ellipse, the row keeping t_k itself).
struct OrbitRowPlan {
  std::int64_t every = 1;
  std::optional<OutputTimes> times;  ///< in time
  OrbitAttitudeColumns columns;
};

OrbitRowPlan row_plan(const io::OrbitScenario& sc, const OrbitSimulateArgs& a, double t_end,
                      std::int64_t max_steps, bool to_file) {
  if (a.split) {
    throw InputError(
        "--split: expected a body scenario (the free body's split), found an orbit "
        "scenario ([orbit]): the orbit's splitting has one split");
  }
  OrbitRowPlan p;
  const bool cli_rows = a.every || a.dt_out || a.times;
  p.every = a.every.value_or(cli_rows ? 1 : sc.output.every);
  if (p.every < 1) {
    throw InputError("--every: expected an integer >= 1, found " + std::to_string(p.every));
  }
  const double t0 = sc.integrate.t0;
  if (a.dt_out) p.times = OutputTimes::every(*a.dt_out, t0, t_end);
  if (a.times) p.times = output_times_option("--times", *a.times, t0, t_end);
  const char* name = a.times ? "--times" : "--dt-out";
  if (p.times && !to_file) {
    throw InputError(std::string(name) +
                     ": output times need a CSV file: give --out or [output] file");
  }
  if (p.times && p.times->size() > max_steps) {
    throw InputError(std::string(name) + ": " + std::to_string(p.times->size()) +
                     " output times, more than max_steps = " + std::to_string(max_steps));
  }
  if ((a.attitude || a.euler) && !to_file) {
    throw InputError(std::string(a.euler ? "--euler" : "--attitude") +
                     ": the attitude columns need a CSV file: give --out or [output] file");
  }
  p.columns = {a.attitude || a.euler.has_value(), a.euler.value_or(0)};
  return p;
}

/// The output times in the integrator's variable: t itself, or ν(t_k) by Kepler's equation.
OutputTimes run_times(const io::OrbitScenario& sc, const OutputTimes& t, double nu0, double nu1) {
  const auto* e = std::get_if<EllipticOrbit>(&sc.orbit);
  if (!e) return t;
  std::vector<double> nu;
  nu.reserve(static_cast<std::size_t>(t.size()));
  for (std::int64_t k = 0; k < t.size(); ++k) {
    nu.push_back(true_anomaly_at(*e, t[k] - sc.integrate.t0));
  }
  return OutputTimes::list(std::move(nu), nu0, nu1);
}

}  // namespace

int orbit_simulate(const std::string& path, const OrbitSimulateArgs& a) {
  const io::OrbitScenario sc = io::load_orbit_scenario(path);
  warn_units(sc);
  const MethodSettings method = orbit_method(sc, a.method, a.step, a.tol);
  const double t_end = a.times && !a.t_end && !sc.integrate.t_end
                           ? times_end("--times", parse_times("--times", *a.times), sc.integrate.t0)
                           : orbit_t_end(sc, a.t_end);
  if (!(t_end > sc.integrate.t0)) {
    throw InputError("--times: expected times after t0 = " + format_number(sc.integrate.t0));
  }
  const std::optional<std::string> out_path = a.out ? a.out : sc.output.file;
  if (out_path && out_path->size() >= 3 && out_path->substr(out_path->size() - 3) == ".h5") {
    throw InputError("--out: expected a CSV file name, found " + *out_path +
                     ": simulate writes CSV trajectories (HDF5 is written by sweep)");
  }
  const double t0 = sc.integrate.t0;
  const std::int64_t max_steps = sc.integrate.max_steps.value_or(100'000'000);
  const OrbitRowPlan plan = row_plan(sc, a, t_end, max_steps, out_path.has_value());

  std::unique_ptr<io::AtomicFile> file;
  if (out_path) {
    file = std::make_unique<io::AtomicFile>(*out_path);
    file->stream() << orbit_csv_header(sc, plan.columns) << '\n';
  }
  const OrbitValues initial = orbit_values(sc, sc.initial, start_variable(sc));
  OrbitSectionDrift drift;  // the integral of the run (Jacobi's or H_nu) and the Casimirs
  drift.observe(sc.initial, &initial.integral);
  double max_casimir_error = 0.0;
  std::int64_t count = 0;
  double last = std::nan("");
  // The observer's variable is t (circular) or ν (elliptic); rows carry the time.
  auto time_of = [&](double x) { return orbit_time(sc, x, t0); };
  auto observer = [&](double x, const OrbitState& s) {
    const OrbitValues v = orbit_values(sc, s, x);
    drift.observe(s, &v.integral);
    max_casimir_error = std::max(max_casimir_error, v.casimir);
    if (file && !plan.times && count % plan.every == 0) {
      file->stream() << orbit_csv_row(sc, s, x, plan.columns) << '\n';
      last = x;
    }
    ++count;
  };
  auto sample = [&](std::int64_t k, double x, const OrbitState& s) {
    file->stream() << orbit_csv_row(sc, s, x, plan.columns, (*plan.times)[k]) << '\n';
  };
  OrbitOutcome out;
  if (const auto* c = std::get_if<CircularOrbit>(&sc.orbit)) {
    const CircularOrbitModel model(sc.body, *c);
    out = plan.times ? run_orbit_method_sampled(method, model, sc.initial, t0, t_end, *plan.times,
                                                max_steps, sample, observer)
                     : run_orbit_method(method, model, sc.initial, t0, t_end, max_steps, observer);
  } else {
    const auto& e = std::get<EllipticOrbit>(sc.orbit);
    const EllipticOrbitModel model(sc.body, e);
    const double nu0 = e.true_anomaly0, nu1 = true_anomaly_at(e, t_end - t0);
    out = plan.times ? run_orbit_method_sampled(method, model, sc.initial, nu0, nu1,
                                                run_times(sc, *plan.times, nu0, nu1), max_steps,
                                                sample, observer)
                     : run_orbit_method(method, model, sc.initial, nu0, nu1, max_steps, observer);
  }
  if (file && !plan.times && last != out.t) {
    file->stream() << orbit_csv_row(sc, out.state, out.t, plan.columns) << '\n';
  }
  if (file) file->commit();
  const OrbitRunReport rep{sc,
                           method,
                           out,
                           time_of(out.t),
                           initial,
                           orbit_values(sc, out.state, out.t),
                           {drift.jacobi, max_casimir_error},
                           drift.gamma_gamma,
                           out_path};
  if (a.json) {
    print_json(std::cout, orbit_simulation_json(rep));
  } else {
    print_orbit_simulation(std::cout, rep);
  }
  return out.status == Status::finished ? 0 : 3;
}

int orbit_integrals(const std::string& path, bool json) {
  const io::OrbitScenario sc = io::load_orbit_scenario(path);
  warn_units(sc);
  const OrbitValues v = orbit_values(sc, sc.initial, start_variable(sc));
  io::Json j;
  j["integrals"] = orbit_values_json(sc, v);
  j["conserved"] = sc.circular()
                       ? io::Json::array({"jacobi", "gamma_gamma", "normal_normal", "gamma_normal"})
                       : io::Json::array({"gamma_gamma", "normal_normal", "gamma_normal"});
  j["model"] = orbit_model_json(sc);
  if (json) {
    print_json(std::cout, j);
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
