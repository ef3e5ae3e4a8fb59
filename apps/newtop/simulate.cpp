// newtop simulate SCENARIO.toml: integrate the Euler–Poisson equations, report integrals' drift.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "cli.hpp"
#include "command.hpp"
#include "integration_options.hpp"
#include "interrupt.hpp"
#include "newtop/exact/multipole.hpp"
#include "newtop/integrate/run.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "orbit_commands.hpp"
#include "summary.hpp"
#include "times_option.hpp"

namespace newtop::app {
namespace {

struct SimulateArgs {
  std::string scenario;
  std::optional<double> t_end, step, tol, dt_out;
  std::optional<std::string> method, split, out, times;
  std::optional<int> euler;
  std::optional<std::int64_t> every;
  bool attitude = false;
  bool json = false;
};

/// Everything a run needs, checked before any work is done.
struct RunPlan {
  MethodSettings method;
  double t0 = 0, t_end = 0;
  IntegrateOptions options;
  std::optional<std::string> out_path;
  std::int64_t every = 1;
  std::optional<OutputTimes> times;  ///< rows at these times instead of every N-th step
};

RunPlan make_plan(const SimulateArgs& a, const io::Scenario& sc) {
  RunPlan p;
  const io::IntegrateOverrides ov{a.method, a.step, a.tol, a.t_end, a.split};
  p.method = io::resolve_method(sc, ov);
  p.t0 = sc.integrate.t0;
  if (!a.t_end && !sc.integrate.t_end && a.times) {
    p.t_end = times_end("--times", parse_times("--times", *a.times), p.t0);
  } else {
    p.t_end = io::resolve_t_end(sc, ov);
  }
  if (sc.integrate.max_steps) p.options.max_steps = *sc.integrate.max_steps;
  check_run_span(sc, p.method, p.t0, p.t_end, p.options);
  p.out_path = a.out ? a.out : sc.output.file;
  const bool cli_rows = a.every || a.dt_out || a.times;  // the command line overrides [output]
  p.every = a.every.value_or(cli_rows ? 1 : sc.output.every);
  if (p.every < 1) {
    throw InputError("--every: expected an integer >= 1, found " + std::to_string(p.every));
  }
  const std::optional<double> dt = a.dt_out ? a.dt_out : (cli_rows ? std::nullopt : sc.output.dt);
  if (dt) p.times = OutputTimes::every(*dt, p.t0, p.t_end);
  if (a.times) p.times = output_times_option("--times", *a.times, p.t0, p.t_end);
  if (p.times && p.times->size() > p.options.max_steps) {
    // Each row costs at least one step of a fixed-step method and one CSV line of any method.
    throw InputError(std::string(a.times    ? "--times"
                                 : a.dt_out ? "--dt-out"
                                            : "[output] dt") +
                     ": " + std::to_string(p.times->size()) +
                     " output times, more than max_steps = " + std::to_string(p.options.max_steps) +
                     (sc.integrate.max_steps ? " ([integrate] max_steps)" : " (the default)"));
  }
  if (p.times && !p.out_path) {
    throw InputError(std::string(a.times ? "--times" : "--dt-out") +
                     ": output times need a CSV file: give --out or [output] file");
  }
  return p;
}

/// Runs the plan from x0 (a State, or an OrientedState with the attitude), writing the CSV rows;
/// every step is checked for a pending SIGINT/SIGTERM.
template <class X>
Outcome run_plan(const RunPlan& p, const Model& model, const X& x0, IntegralsDrift& drift,
                 io::CsvTrajectory* csv) {
  std::int64_t count = 0;
  double last_written = std::nan("");
  auto on_step = [&](double t, const X& s) {
    throw_if_interrupted(t);
    drift.observe(model, s);
    if (csv && !p.times && count % p.every == 0) {
      csv->write(t, s);
      last_written = t;
    }
    ++count;
  };
  if (p.times) {
    auto on_sample = [&](std::int64_t, double t, const X& s) { csv->write(t, s); };
    return run_method_sampled(p.method, model, x0, p.t0, p.t_end, *p.times, p.options, on_sample,
                              on_step);
  }
  const Outcome out = run_method(p.method, model, x0, p.t0, p.t_end, p.options, on_step);
  if (csv && last_written != out.t) {  // always end on the last state
    if constexpr (kOriented<X>) {
      csv->write(out.t, with_attitude(out.state, *out.attitude));
    } else {
      csv->write(out.t, out.state);
    }
  }
  return out;
}

/// The summary or the JSON; with an exact or multipole field, the quadratic model's run `q` beside.
void print_report(const SimulateArgs& a, const io::Scenario& sc, SimulationReport& rep,
                  const std::optional<Outcome>& q) {
  if (!q) {
    if (a.json) {
      print_json(std::cout, simulation_json(rep));
    } else {
      print_simulation_summary(std::cout, rep);
    }
    return;
  }
  const State& x = rep.outcome.state;
  const Body& body = sc.model.body();
  const Vec3 dw = omega(body, x) - omega(body, q->state);
  const double dg = (x.gamma - q->state.gamma).norm();
  if (a.json) {
    io::Json j = simulation_json(rep);
    j["quadratic_comparison"] = {{"outcome", std::string(to_string(q->status))},
                                 {"gamma", io::to_json(q->state.gamma)},
                                 {"omega", io::to_json(omega(body, q->state))},
                                 {"difference_gamma", dg},
                                 {"difference_omega", dw.norm()}};
    print_json(std::cout, j);
    return;
  }
  print_simulation_summary(std::cout, rep);
  std::cout << "quadratic model, same method: |gamma - gamma_q| = " << format_number(dg)
            << "   |omega - omega_q| = " << format_number(dw.norm()) << "\n";
}

int run_in(const SimulateArgs& a, const io::Scenario& sc) {
  const Model& model = sc.model;
  const RunPlan plan = make_plan(a, sc);
  if ((a.euler || a.attitude) && !sc.attitude) {
    throw InputError(std::string(a.euler ? "--euler" : "--attitude") +
                     ": expected a scenario with an attitude ([initial] quaternion, "
                     "rotation_matrix, euler_321 or euler_313), found none in " +
                     sc.source);
  }
  std::unique_ptr<io::AtomicFile> file;
  std::unique_ptr<io::CsvTrajectory> csv;
  if (plan.out_path) {
    file = std::make_unique<io::AtomicFile>(*plan.out_path, sc.input_files);
    // The CSV's integral columns are those of the run's own field; with an attitude, q0..q3.
    csv = std::make_unique<io::CsvTrajectory>(
        file->stream(), sc.model,
        io::AttitudeColumns{sc.attitude.has_value(), a.euler.value_or(0)});
  }
  IntegralsDrift drift;  // from the start; max |m| over the run's states
  drift.observe(integrals(model, sc.initial));
  const Outcome out =
      sc.attitude ? run_plan(plan, model, with_attitude(sc.initial, *sc.attitude), drift, csv.get())
                  : run_plan(plan, model, sc.initial, drift, csv.get());
  // Exact or multipole field: the same run in the quadratic model, for comparison.
  std::optional<Outcome> q;
  if (sc.model.kind() != FieldKind::quadratic) {
    auto check = [](double t, const State&) { throw_if_interrupted(t); };
    q = run_method(plan.method, quadratic_approximation(sc.model), sc.initial, plan.t0, plan.t_end,
                   plan.options, check);
  }
  throw_if_interrupted(out.t);
  if (file) file->commit();

  SimulationReport rep{
      sc,           plan.method, out, drift.initial, integrals(model, out.state), drift.max_drift,
      plan.out_path};
  rep.casimir = casimir_drift(drift);
  if (rep.casimir.exceeded()) warn(casimir_warning(rep.casimir));
  print_report(a, sc, rep, q);
  return out.status == Status::finished ? kExitOk : kExitIncomplete;
}

int run(const SimulateArgs& a) {
  if (a.out && a.out->size() >= 3 && a.out->substr(a.out->size() - 3) == ".h5") {
    throw InputError("--out: expected a CSV file name, found " + *a.out +
                     ": simulate writes CSV trajectories (HDF5 is written by sweep)");
  }
  if (io::is_orbit_scenario(a.scenario)) {
    return orbit_simulate(a.scenario, {a.t_end, a.step, a.tol, a.dt_out, a.method, a.out, a.times,
                                       a.split, a.every, a.euler, a.attitude, a.json});
  }
  const io::Scenario sc = io::load_scenario(a.scenario);
  const InterruptGuard guard;
  try {
    return run_in(a, sc);
  } catch (const Interrupted& e) {
    std::cerr << "newtop: interrupted by " << signal_name(e.signal)
              << " at t = " << format_number(e.t)
              << (a.out || sc.output.file ? "; the output file was not written" : "") << '\n';
    return 128 + e.signal;
  }
}

const RegisterCommand reg_simulate{Command{
    "simulate", "Integrate a scenario and report the final state and the drift of the integrals",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<SimulateArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      add_integration_options(sub, a->t_end, a->method, a->step, a->tol, a->split);
      sub.add_option("--out", a->out, "write the trajectory to this CSV file");
      auto* every =
          sub.add_option("--every", a->every, "write every N-th step to the CSV (default 1)");
      auto* dt = sub.add_option("--dt-out", a->dt_out,
                                "write CSV rows at t0 + k*D (dense output; overrides [output] dt)");
      auto* times = sub.add_option("--times", a->times,
                                   "write CSV rows at these comma-separated times (t_end defaults "
                                   "to the last)");
      every->excludes(dt)->excludes(times);
      dt->excludes(times);
      sub.add_option("--euler", a->euler,
                     "with an attitude: add the Euler angles 321 (psi, theta, phi) or 313 (phi, "
                     "theta, psi) to the CSV (321 or 313)");
      sub.add_flag("--attitude", a->attitude,
                   "write the attitude q0..q3 (with an attitude; on an orbit: LVLH -> body, see "
                   "newtop --help)");
      sub.add_flag("--json", a->json, "print one JSON object instead of the summary");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
