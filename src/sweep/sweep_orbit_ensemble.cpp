// Points of an orbit sweep run with method taylor, advanced together by the orbit's Taylor ensemble
// (sweep_points.hpp, evaluate_orbit_taylor_points). Each group's runs are sweep_orbit.cpp's
// run_orbit (final_state, drift) or run_orbit_chaos (megno, lyapunov_max), point by point in
// lanes: the same settings (resolve_method, resolve_t_end, the step limit), the same options (the
// first trial step |b − a|/1000), the drift observed from the start and after every accepted step,
// or the chaos indicators accumulated after every accepted step at its time; the ensemble gives
// each trajectory the scalar run's bits, so each point's result is evaluate_orbit_point's.

#include <algorithm>
#include <cmath>
#include <variant>

#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/orbit_settings.hpp"
#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_taylor_ensemble.hpp"
#include "sweep_points.hpp"

namespace newtop::sweep {
namespace orbit_ensemble {  // named: the library is compiled in unity batches
namespace {

constexpr std::size_t kSmallestGroup = 4;  // as sweep_ensemble.cpp's groups

/// What the points of a group share (the model is each point's own).
struct OrbitKey {
  MethodSettings method;
  bool elliptic = false;
  double a = 0, b = 0;  // the run's start and end: t, or ν on an ellipse
  std::int64_t max_steps = 0;
};

bool same_run(const OrbitKey& x, const OrbitKey& y) {
  return x.method.name == y.method.name && x.method.abs_tol == y.method.abs_tol &&
         x.method.rel_tol == y.method.rel_tol && x.elliptic == y.elliptic && x.a == y.a &&
         x.b == y.b && x.max_steps == y.max_steps;
}

struct Member {
  std::size_t slot;
  io::OrbitScenario sc;
};

struct Group {
  OrbitKey key;
  std::vector<Member> members;
};

/// The point's run settings as run_orbit resolves them, or nullopt for a point that does not run
/// with method taylor (it then runs point by point).
std::optional<OrbitKey> run_key(const SweepFile& s, const io::OrbitScenario& sc) {
  const MethodSettings method = io::resolve_method(sc, s.integrate);
  if (method.name != "taylor" || !is_finite(sc.initial)) return std::nullopt;
  const double t0 = sc.integrate.t0, t1 = io::resolve_t_end(sc, s.integrate);
  OrbitKey k{method, false, t0, t1, sc.integrate.max_steps.value_or(100'000'000)};
  if (const auto* e = std::get_if<EllipticOrbit>(&sc.orbit)) {
    k.elliptic = true;
    k.a = e->true_anomaly0;
    k.b = true_anomaly_at(*e, t1 - t0);
  }
  return k;
}

/// A group of chaos runs (megno, lyapunov_max): orbit_chaos's tangent run of each point
/// (run_orbit_chaos), the indicators accumulated per point at the time of each step.
void run_chaos_group(const SweepFile& s, const Group& g,
                     std::vector<std::optional<PointResult>>& out) {
  const OrbitKey& k = g.key;
  OrbitChaosSettings check;
  check.method = k.method;
  check.t0 = g.members[0].sc.integrate.t0;
  check.t1 = io::resolve_t_end(g.members[0].sc, s.integrate);
  check_orbit_chaos_settings(check);
  OrbitTaylorEnsemble ensemble(k.method.abs_tol, k.method.rel_tol);
  IntegrateOptions options;  // orbit_chaos's
  options.max_steps = k.max_steps;
  options.initial_step = std::abs(k.b - k.a) / 1000.0;
  const std::size_t n = g.members.size();
  std::vector<OrbitState> x;
  std::vector<phase::ChaosIndicators> ind;
  for (const Member& p : g.members) {
    x.push_back(p.sc.initial);
    ind.emplace_back(p.sc.integrate.t0, 1);
  }
  std::vector<OrbitOutcome> outcomes;
  auto grow = [&](std::size_t j, double t, double log_growth) {
    std::array<double, 6> growth{};
    growth[0] = log_growth;
    ind[j].accumulate(t, growth);
  };
  if (k.elliptic) {
    std::vector<EllipticOrbitModel> models;
    for (const Member& p : g.members) {
      models.emplace_back(p.sc.body, std::get<EllipticOrbit>(p.sc.orbit));
    }
    outcomes = ensemble.integrate_chaos(models, x, k.a, k.b, options,
                                        [&](std::size_t j, double nu, const OrbitState&, double d) {
                                          const double t0 = g.members[j].sc.integrate.t0;
                                          grow(j, t0 + elapsed_time(models[j].orbit(), k.a, nu), d);
                                        });
  } else {
    std::vector<CircularOrbitModel> models;
    for (const Member& p : g.members) {
      models.emplace_back(p.sc.body, std::get<CircularOrbit>(p.sc.orbit));
    }
    outcomes = ensemble.integrate_chaos(
        models, x, k.a, k.b, options,
        [&](std::size_t j, double t, const OrbitState&, double d) { grow(j, t, d); });
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (outcomes[j].status != Status::finished) {
      out[g.members[j].slot] = PointResult{std::string(to_string(outcomes[j].status)), {}};
      continue;
    }
    const phase::ChaosSample c = ind[j].sample();
    PointResult r{"ok", {}};
    for (const std::string& q : s.quantities) {
      r.values.push_back(q == "megno" ? c.megno : c.lyapunov_max);
    }
    out[g.members[j].slot] = std::move(r);
  }
}

void run_group(const SweepFile& s, const Group& g, std::vector<std::optional<PointResult>>& out) {
  const OrbitKey& k = g.key;
  if (wants(s, "megno") || wants(s, "lyapunov_max")) return run_chaos_group(s, g, out);
  validate_orbit_method(k.method);
  OrbitTaylorEnsemble ensemble(k.method.abs_tol, k.method.rel_tol);
  IntegrateOptions options;  // run_orbit_method's
  options.max_steps = k.max_steps;
  options.initial_step = std::abs(k.b - k.a) / 1000.0;
  const std::size_t n = g.members.size();
  std::vector<OrbitState> x;
  std::vector<OrbitRun> runs(n);
  for (const Member& p : g.members) x.push_back(p.sc.initial);
  std::vector<OrbitOutcome> outcomes;
  if (k.elliptic) {
    std::vector<EllipticOrbitModel> models;
    for (std::size_t j = 0; j < n; ++j) {
      const io::OrbitScenario& sc = g.members[j].sc;
      models.emplace_back(sc.body, std::get<EllipticOrbit>(sc.orbit));
      runs[j].drift.observe(sc.initial, nullptr);
    }
    outcomes = ensemble.integrate(
        models, x, k.a, k.b, options,
        [&](std::size_t j, double, const OrbitState& y) { runs[j].drift.observe(y, nullptr); });
  } else {
    std::vector<CircularOrbitModel> models;
    for (std::size_t j = 0; j < n; ++j) {
      const io::OrbitScenario& sc = g.members[j].sc;
      models.emplace_back(sc.body, std::get<CircularOrbit>(sc.orbit));
      const double h0 = jacobi_integral(models.back(), sc.initial);
      runs[j].drift.observe(sc.initial, &h0);
    }
    outcomes = ensemble.integrate(models, x, k.a, k.b, options,
                                  [&](std::size_t j, double, const OrbitState& y) {
                                    const double h = jacobi_integral(models[j], y);
                                    runs[j].drift.observe(y, &h);
                                  });
  }
  for (std::size_t j = 0; j < n; ++j) {
    const io::OrbitScenario& sc = g.members[j].sc;
    OrbitRun& r = runs[j];
    r.outcome = outcomes[j];
    r.t = r.outcome.t;
    if (k.elliptic) {  // run_orbit's time reached
      const double t0 = sc.integrate.t0, t1 = io::resolve_t_end(sc, s.integrate);
      r.t = r.outcome.t == k.b
                ? t1
                : t0 + elapsed_time(std::get<EllipticOrbit>(sc.orbit), k.a, r.outcome.t);
    }
    out[g.members[j].slot] = orbit_run_result(s, sc, r);
  }
}

}  // namespace
}  // namespace orbit_ensemble

void evaluate_orbit_taylor_points(const SweepFile& s, std::span<const std::size_t> indices,
                                  std::vector<std::optional<PointResult>>& out, std::size_t* runs) {
  namespace oe = orbit_ensemble;
  std::vector<oe::Group> groups;
  for (std::size_t slot = 0; slot < indices.size(); ++slot) {
    try {
      io::OrbitScenario sc = orbit_point_scenario(s, indices[slot]);
      const std::optional<oe::OrbitKey> key = oe::run_key(s, sc);
      if (!key) continue;
      auto g = std::find_if(groups.begin(), groups.end(),
                            [&](const oe::Group& x) { return oe::same_run(x.key, *key); });
      if (g == groups.end()) g = groups.insert(groups.end(), oe::Group{*key, {}});
      g->members.push_back(oe::Member{slot, std::move(sc)});
    } catch (const std::exception&) {  // evaluate_point_safely reports it
    }
  }
  std::erase_if(groups, [](const oe::Group& g) { return g.members.size() < oe::kSmallestGroup; });
  if (runs) *runs = groups.size();
  for (const oe::Group& g : groups) {
    try {
      oe::run_group(s, g, out);
    } catch (const std::exception&) {  // the same error at every point: reported point by point
      for (const oe::Member& p : g.members) out[p.slot].reset();
    }
  }
}

}  // namespace newtop::sweep
