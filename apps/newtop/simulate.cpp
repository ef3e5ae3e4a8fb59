// newtop simulate SCENARIO.toml: integrate the Euler–Poisson equations, report integrals' drift.

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "newtop/exact/multipole.hpp"
#include "newtop/integrate/methods.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct SimulateArgs {
  std::string scenario;
  std::optional<double> t_end, step, tol;
  std::optional<std::string> method, out;
  std::optional<std::int64_t> every;
  bool json = false;
};

/// Tracks max |I(t) − I(0)| of every integral that holds.
template <class M>
struct DriftTracker {
  const M& model;
  IntegralValues initial, max_drift;
  void observe(const State& s) {
    const IntegralValues v = integrals(model, s);
    auto upd = [](double& m, double a, double b) { m = std::max(m, std::abs(a - b)); };
    upd(max_drift.energy, v.energy, initial.energy);
    upd(max_drift.area, v.area, initial.area);
    upd(max_drift.geometric, v.geometric, initial.geometric);
    if (v.brun) upd(*max_drift.brun, *v.brun, *initial.brun);
    if (v.lagrange) upd(*max_drift.lagrange, *v.lagrange, *initial.lagrange);
  }
};

const char* kind_name(io::FieldKind k) {
  return k == io::FieldKind::exact       ? "exact"
         : k == io::FieldKind::multipole ? "multipole"
                                         : "quadratic";
}

template <class M>
int run_in(const SimulateArgs& a, const io::Scenario& sc, const M& model) {
  const io::IntegrateOverrides ov{a.method, a.step, a.tol, a.t_end};
  const MethodSettings method = io::resolve_method(sc, ov);
  const double t_end = io::resolve_t_end(sc, ov);
  const std::optional<std::string> out_path = a.out ? a.out : sc.output.file;
  const std::int64_t every = a.every.value_or(sc.output.every);
  if (every < 1)
    throw InputError("--every: expected an integer >= 1, found " + std::to_string(every));

  IntegrateOptions options;
  if (sc.integrate.max_steps) options.max_steps = *sc.integrate.max_steps;

  std::unique_ptr<io::AtomicFile> file;
  std::unique_ptr<io::CsvTrajectory> csv;
  if (out_path) {
    file = std::make_unique<io::AtomicFile>(*out_path);
    // The CSV's integral columns are those of the quadratic model (docs/exact_field.md).
    csv = std::make_unique<io::CsvTrajectory>(file->stream(), sc.model);
  }
  const IntegralValues initial = integrals(model, sc.initial);
  IntegralValues zero = initial;
  zero.energy = zero.area = zero.geometric = 0.0;
  if (zero.brun) zero.brun = 0.0;
  if (zero.lagrange) zero.lagrange = 0.0;
  DriftTracker<M> drift{model, initial, zero};
  std::int64_t count = 0;
  double last_written = std::nan("");
  auto observer = [&](double t, const State& s) {
    drift.observe(s);
    if (csv && count % every == 0) {
      csv->write(t, s);
      last_written = t;
    }
    ++count;
  };
  const Outcome out =
      run_method(method, model, sc.initial, sc.integrate.t0, t_end, options, observer);
  if (csv && last_written != out.t) csv->write(out.t, out.state);  // always end on the last state
  if (file) file->commit();

  const IntegralValues final_values = integrals(model, out.state);
  SimulationReport rep{sc, method, out, initial, final_values, drift.max_drift, out_path};
  if (sc.exact.kind == io::FieldKind::quadratic) {
    if (a.json) {
      std::cout << simulation_json(rep).dump(2) << '\n';
    } else {
      print_simulation_summary(std::cout, rep);
    }
    return out.status == Status::finished ? kExitOk : kExitIncomplete;
  }
  // Exact or multipole field: the same run in the quadratic model, and the difference.
  const Outcome q = run_method(method, sc.model, sc.initial, sc.integrate.t0, t_end, options);
  const Vec3 dw = omega(sc.model.body, out.state) - omega(sc.model.body, q.state);
  const double dg = (out.state.gamma - q.state.gamma).norm();
  if (a.json) {
    io::Json j = simulation_json(rep);
    j["field"] = {{"kind", kind_name(sc.exact.kind)}, {"mu", sc.exact.mu}, {"R", sc.exact.R}};
    if (sc.exact.kind == io::FieldKind::multipole) j["field"]["order"] = sc.exact.order;
    j["quadratic_comparison"] = {{"outcome", std::string(to_string(q.status))},
                                 {"gamma", io::to_json(q.state.gamma)},
                                 {"omega", io::to_json(omega(sc.model.body, q.state))},
                                 {"difference_gamma", dg},
                                 {"difference_omega", dw.norm()}};
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << "field     " << kind_name(sc.exact.kind) << " (mu = " << format_number(sc.exact.mu)
              << ", R = " << format_number(sc.exact.R) << ")\n";
    print_simulation_summary(std::cout, rep);
    std::cout << "quadratic model, same method: |gamma - gamma_q| = " << format_number(dg)
              << "   |omega - omega_q| = " << format_number(dw.norm()) << "\n";
  }
  return out.status == Status::finished ? kExitOk : kExitIncomplete;
}

/// The field of the run: the quadratic model, or the exact field / its expansion of [mass_model].
template <class Run>
auto with_field(const io::Scenario& sc, Run&& run) {
  const io::ExactSettings& e = sc.exact;
  const Mat3& P = sc.model.body.principal_axes();
  switch (e.kind) {
    case io::FieldKind::exact:
      return run(
          BasicModel<ExactField>{sc.model.body, ExactField::make(e.mass_model, e.mu, e.R, P)});
    case io::FieldKind::multipole:
      return run(BasicModel<MultipoleField>{
          sc.model.body, MultipoleField::make(*e.mass_model, e.order, e.mu, e.R, P)});
    case io::FieldKind::quadratic:
      break;
  }
  return run(sc.model);
}

int run(const SimulateArgs& a) {
  const io::Scenario sc = io::load_scenario(a.scenario);
  return with_field(sc, [&](const auto& model) { return run_in(a, sc, model); });
}

const RegisterCommand reg{Command{
    "simulate", "Integrate a scenario and report the final state and the drift of the integrals",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<SimulateArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      sub.add_option("--t-end", a->t_end, "final time (overrides [integrate] t_end)");
      sub.add_option("--method", a->method,
                     "method: splitting2, splitting4, splitting4-yoshida, splitting6, splitting8, "
                     "splitting8-mclachlan, rk4, dopri5, rkf78");
      auto* step = sub.add_option("--step", a->step, "fixed step (selects splitting6 by default)");
      auto* tol = sub.add_option("--tol", a->tol,
                                 "absolute and relative tolerance (selects rkf78 by default)");
      step->excludes(tol);
      sub.add_option("--out", a->out, "write the trajectory to this CSV file");
      sub.add_option("--every", a->every, "write every N-th step to the CSV (default 1)");
      sub.add_flag("--json", a->json, "print one JSON object instead of the summary");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
