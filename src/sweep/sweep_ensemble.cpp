// Points of a sweep advanced together by the ensemble stepper (sweep_ensemble.hpp). A group's run
// follows the fixed-step driver (driver.hpp, detail::fixed_steps) step for step: n equal steps of
// (t_end − t0)/n, a step limit checked before each step, a non-finite state ending the point's run,
// the drift observed after every step; so each point's result is evaluate_point's, bit for bit.

#include "newtop/sweep/sweep_ensemble.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "newtop/integrate/driver.hpp"
#include "newtop/integrate/ensemble.hpp"
#include "newtop/integrate/method_settings.hpp"
#include "newtop/integrate/taylor_ensemble.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/phase/chaos.hpp"
#include "newtop/phase/chaos_ensemble.hpp"
#include "newtop/phase/ensemble_tangent.hpp"
#include "newtop/phase/tangent_vectors.hpp"
#include "sweep_points.hpp"

namespace newtop::sweep {
namespace {

constexpr std::size_t kSmallestGroup = 4;

bool only(const SweepFile& s, const char* a, const char* b) {
  return !s.quantities.empty() &&
         std::all_of(s.quantities.begin(), s.quantities.end(),
                     [&](const std::string& q) { return q == a || q == b; });
}

/// megno and lyapunov_max only: the tangent run of newtop chaos (one tangent vector).
bool tangent_sweep(const SweepFile& s) { return only(s, "megno", "lyapunov_max"); }

/// What the points of a group share: the run's settings as evaluate_point resolves them (the model
/// is the point's own: the ensemble holds a model per lane).
struct RunKey {
  MethodSettings method;
  SplitOrdering ordering;  // method.ordering or the table's default
  double t0 = 0, t1 = 0;
  std::int64_t max_steps = 0;
};

bool same_model(const QuadraticModel& a, const QuadraticModel& b) {
  const Body &x = a.body, &y = b.body;
  return x.inertia() == y.inertia() && x.mass() == y.mass() &&
         x.center_of_mass() == y.center_of_mass() && x.gyrostat() == y.gyrostat() &&
         a.field.g == b.field.g && a.field.lambda_ == b.field.lambda_;
}

bool same_run(const RunKey& a, const RunKey& b) {
  const SplitOrdering &p = a.ordering, &q = b.ordering;
  return a.method.name == b.method.name && a.method.step == b.method.step &&
         a.method.abs_tol == b.method.abs_tol && a.method.rel_tol == b.method.rel_tol &&
         p.axes == q.axes && p.kick_outside == q.kick_outside && p.by_moment == q.by_moment &&
         p.free_body == q.free_body && a.t0 == b.t0 && a.t1 == b.t1 && a.max_steps == b.max_steps;
}

struct Member {
  std::size_t slot;          // position in `indices`
  Model model;               // the point's own (for its integrals and ω)
  QuadraticModel quadratic;  // the same, for the stepper
  State initial;
};

struct Group {
  RunKey key;
  std::vector<Member> members;
};

/// The point's run settings, or nullopt when the point is not for an ensemble (another field or
/// method, a non-finite initial state, or a scenario that does not build: evaluate_point_safely
/// then reports it).
std::optional<RunKey> run_key(const SweepFile& s, const io::Scenario& sc) {
  if (sc.model.kind() != FieldKind::quadratic || !is_finite(sc.initial)) return std::nullopt;
  const MethodSettings method = io::resolve_method(sc, s.integrate);
  if (method.name == "taylor") {  // the Taylor ensemble
    return RunKey{method, SplitOrdering{}, sc.integrate.t0, io::resolve_t_end(sc, s.integrate),
                  sc.integrate.max_steps.value_or(IntegrateOptions{}.max_steps)};
  }
  if (method_info(method.name).kind != MethodKind::splitting) return std::nullopt;
  const SplitOrdering ordering =
      method.ordering.value_or(default_ordering(composition_table(method.name)));
  // The ensemble tangent kernels have the axes split only: other splits run point by point.
  if (tangent_sweep(s) && ordering.free_body != FreeBodySplit::axes) return std::nullopt;
  return RunKey{method, ordering, sc.integrate.t0, io::resolve_t_end(sc, s.integrate),
                sc.integrate.max_steps.value_or(IntegrateOptions{}.max_steps)};
}

/// The values of evaluate_point for a finished run.
PointResult finished(const SweepFile& s, const Member& p, double t, const State& x,
                     const IntegralsDrift& drift) {
  PointResult r{"ok", {}};
  for (const std::string& q : s.quantities) {
    if (q == "drift") {
      const IntegralValues& d = drift.max_drift;
      r.values.insert(r.values.end(), {d.energy, d.area, d.geometric});
    } else if (q == "final_state") {
      const Vec3 w = omega(p.model.body(), x);
      r.values.insert(r.values.end(),
                      {t, w.x(), w.y(), w.z(), x.gamma.x(), x.gamma.y(), x.gamma.z()});
    }
  }
  return r;
}

/// Runs a group; throws what the scalar run would throw for its shared settings.
void run_group(const SweepFile& s, const Group& g, std::vector<std::optional<PointResult>>& out) {
  const RunKey& k = g.key;
  validate(k.method);
  IntegrateOptions options;
  options.max_steps = k.max_steps;
  check_options(options);
  const std::int64_t n = fixed_step_count(k.t0, k.t1, k.method.step);
  EnsembleStepper stepper(composition_table(k.method.name), k.ordering);

  EnsembleState x;
  std::vector<IntegralsDrift> drift(g.members.size());
  std::vector<QuadraticModel> models;
  for (std::size_t j = 0; j < g.members.size(); ++j) {
    const Member& p = g.members[j];
    x.push_back(p.initial);
    drift[j].observe(integrals(p.model, p.initial));
    models.push_back(p.quadratic);
  }
  // One model for all: its constants splatted; several (a sweep over the body or the field): a
  // model per lane. Either way each point's run is the scalar stepper's on its own model.
  const bool one_model = std::all_of(models.begin(), models.end(), [&](const QuadraticModel& m) {
    return same_model(m, models.front());
  });
  const std::optional<EnsembleModels> lanes =
      one_model ? std::nullopt : std::optional<EnsembleModels>(std::in_place, models, k.ordering);
  const std::size_t size = g.members.size();
  std::vector<bool> alive(size, true);
  // A non-finite component stays non-finite through every rotation, spin and kick (each adds to
  // it), so without an observer the state is checked every `chunk` steps; the exact free-body
  // flow and the drift are checked after every step, as the driver does.
  const bool every_step = wants(s, "drift") || k.ordering.free_body == FreeBodySplit::exact;
  const std::int64_t chunk = every_step ? 1 : 256;
  const std::int64_t run = std::min(n, k.max_steps);
  const double h = n > 0 ? (k.t1 - k.t0) / static_cast<double>(n) : 0.0;
  for (std::int64_t done = 0; done < run;) {
    const std::int64_t steps = std::min(chunk, run - done);
    if (lanes) {
      stepper.advance(*lanes, x, h, steps);
    } else {
      stepper.advance(models.front(), x, h, steps);
    }
    done += steps;
    for (std::size_t j = 0; j < size; ++j) {
      if (!alive[j]) continue;
      const State xj = x[j];
      if (!is_finite(xj)) {
        alive[j] = false;
        out[g.members[j].slot] = PointResult{std::string(to_string(Status::non_finite)), {}};
      } else if (every_step) {
        drift[j].observe(integrals(g.members[j].model, xj));
      }
    }
  }
  for (std::size_t j = 0; j < size; ++j) {
    if (!alive[j]) continue;
    out[g.members[j].slot] = n > k.max_steps
                                 ? PointResult{std::string(to_string(Status::step_limit)), {}}
                                 : finished(s, g.members[j], n > 0 ? k.t1 : k.t0, x[j], drift[j]);
  }
}

/// A group of Taylor runs through the Taylor ensemble (a model per lane), which reproduces each
/// point's run of the adaptive driver with TaylorStepper bit for bit, every accepted step observed
/// for the drift as evaluate_point's observer does (from t0 on).
void run_taylor_group(const SweepFile& s, const Group& g,
                      std::vector<std::optional<PointResult>>& out) {
  const RunKey& k = g.key;
  validate(k.method);
  IntegrateOptions options;
  options.max_steps = k.max_steps;
  TaylorEnsemble ensemble(k.method.abs_tol, k.method.rel_tol);
  std::vector<State> x;
  std::vector<QuadraticModel> models;
  std::vector<IntegralsDrift> drift(g.members.size());
  for (std::size_t j = 0; j < g.members.size(); ++j) {
    const Member& p = g.members[j];
    x.push_back(p.initial);
    models.push_back(p.quadratic);
    drift[j].observe(integrals(p.model, p.initial));
  }
  TaylorEnsembleObserver obs;
  if (wants(s, "drift")) {
    obs.step = [&](std::size_t j, double, const State& y) {
      drift[j].observe(integrals(g.members[j].model, y));
    };
  }
  const std::vector<Outcome> r = ensemble.integrate(models, x, k.t0, k.t1, options, obs);
  for (std::size_t j = 0; j < r.size(); ++j) {
    out[g.members[j].slot] = r[j].status == Status::finished
                                 ? finished(s, g.members[j], r[j].t, r[j].state, drift[j])
                                 : PointResult{std::string(to_string(r[j].status)), {}};
  }
}

/// A group of Taylor tangent runs (megno, lyapunov_max) through the Taylor ensemble with one
/// tangent vector per point, each the bits of phase::chaos's run with TangentTaylorStepper: the
/// same start vector, the indicators observed (and the vector renormalised) after every step.
void run_taylor_tangent_group(const SweepFile& s, const Group& g,
                              std::vector<std::optional<PointResult>>& out) {
  const RunKey& k = g.key;
  phase::check_tangent_method(k.method);
  IntegrateOptions options;
  options.max_steps = k.max_steps;
  std::vector<State> x;
  std::vector<QuadraticModel> models;
  for (const Member& p : g.members) {
    x.push_back(p.initial);
    models.push_back(p.quadratic);
  }
  const std::vector<phase::ChaosResult> r = phase::taylor_chaos_ensemble(
      models, x, k.t0, k.t1, k.method.abs_tol, k.method.rel_tol, options);
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (r[j].outcome.status != Status::finished) {
      out[g.members[j].slot] = PointResult{std::string(to_string(r[j].outcome.status)), {}};
      continue;
    }
    PointResult p{"ok", {}};
    for (const std::string& q : s.quantities)
      p.values.push_back(q == "megno" ? r[j].indicators.megno : r[j].indicators.lyapunov_max);
    out[g.members[j].slot] = std::move(p);
  }
}

/// A group through the ensemble tangent stepper (a model per lane where the models differ) with one
/// tangent vector per point,
/// as chaos_run (phase/chaos_run.hpp, integrate_tangent) runs each point: n equal steps, the step
/// limit before each step, a non-finite state or tangent ending the point's run, the indicators
/// observed (and the tangent renormalised) after every step. With one tangent vector the ensemble
/// tangent stepper reproduces TangentSplittingStepper bit for bit (its kick forms (∂L/∂γ) δγ
/// exactly as moment_derivative does; test_sweep_ensemble checks every point against
/// evaluate_point), so each point's result is evaluate_point's.
void run_tangent_group(const SweepFile& s, const Group& g,
                       std::vector<std::optional<PointResult>>& out) {
  const RunKey& k = g.key;
  MethodSettings method = k.method;
  method.ordering = k.ordering;
  phase::check_tangent_method(method);
  IntegrateOptions options;
  options.max_steps = k.max_steps;
  options.step = method.step;
  check_options(options);
  const std::int64_t n = fixed_step_count(k.t0, k.t1, options.step);
  phase::EnsembleTangentStepper stepper(composition_table(method.name), k.ordering);
  EnsembleState x;
  for (const Member& p : g.members) x.push_back(p.initial);
  const std::size_t size = g.members.size();
  std::vector<phase::Tangent> V(size, phase::initial_tangent(1));
  std::vector<phase::ChaosIndicators> ind(size, phase::ChaosIndicators(k.t0, 1));
  std::vector<bool> alive(size, true);
  std::vector<QuadraticModel> models;
  for (const Member& p : g.members) models.push_back(p.quadratic);
  const bool one_model = std::all_of(models.begin(), models.end(), [&](const QuadraticModel& m) {
    return same_model(m, models.front());
  });
  const std::optional<EnsembleModels> lanes =
      one_model ? std::nullopt : std::optional<EnsembleModels>(std::in_place, models, k.ordering);
  const double h = n > 0 ? (k.t1 - k.t0) / static_cast<double>(n) : 0.0;
  const std::int64_t run = std::min(n, k.max_steps);
  for (std::int64_t i = 1; i <= run; ++i) {
    if (lanes) {
      stepper.advance(*lanes, x, V, h, 1);
    } else {
      stepper.advance(models.front(), x, V, h, 1);
    }
    const double t = (i == n) ? k.t1 : k.t0 + static_cast<double>(i) * h;
    for (std::size_t j = 0; j < size; ++j) {
      if (!alive[j]) continue;
      if (!is_finite(x[j]) || !V[j].allFinite()) {
        alive[j] = false;
        out[g.members[j].slot] = PointResult{std::string(to_string(Status::non_finite)), {}};
      } else {
        ind[j](t, V[j]);
      }
    }
  }
  for (std::size_t j = 0; j < size; ++j) {
    if (!alive[j]) continue;
    if (n > k.max_steps) {
      out[g.members[j].slot] = PointResult{std::string(to_string(Status::step_limit)), {}};
      continue;
    }
    const phase::ChaosSample c = ind[j].sample();
    PointResult r{"ok", {}};
    for (const std::string& q : s.quantities)
      r.values.push_back(q == "megno" ? c.megno : c.lyapunov_max);
    out[g.members[j].slot] = std::move(r);
  }
}

}  // namespace

bool ensemble_sweep(const SweepFile& s) {
  return only(s, "final_state", "drift") || tangent_sweep(s);
}

std::vector<PointResult> evaluate_points(const SweepFile& s, std::span<const std::size_t> indices,
                                         std::size_t* in_ensemble, std::size_t* runs) {
  std::vector<std::optional<PointResult>> out(indices.size());
  std::vector<Group> groups;
  if (s.model != BaseModel::fixed_point) {
    // Orbit scenarios: final_state and drift, or megno and lyapunov_max, with method taylor
    // through the orbit's Taylor ensemble; anything else point by point.
    if (only(s, "final_state", "drift") || tangent_sweep(s)) {
      evaluate_orbit_taylor_points(s, indices, out, runs);
    } else if (runs) {
      *runs = 0;
    }
  } else if (ensemble_sweep(s)) {
    for (std::size_t slot = 0; slot < indices.size(); ++slot) {
      try {
        const io::Scenario sc = point_scenario(s, indices[slot]);
        const std::optional<RunKey> key = run_key(s, sc);
        if (!key) continue;
        auto g = std::find_if(groups.begin(), groups.end(),
                              [&](const Group& x) { return same_run(x.key, *key); });
        if (g == groups.end()) g = groups.insert(groups.end(), Group{*key, {}});
        g->members.push_back(Member{slot, sc.model, sc.model.quadratic(), sc.initial});
      } catch (const std::exception&) {  // evaluate_point_safely reports it
      }
    }
  }
  // A block of lanes costs about as much as 3 to 4 scalar runs (bench_ensemble: 48 lanes of
  // AVX-512 at 1.2e8 trajectory-steps/s against 9e6 for one scalar trajectory of splitting2; the
  // portable block of 12 lanes, 2.4 runs): smaller groups run point by point (the same bits).
  std::erase_if(groups, [](const Group& g) { return g.members.size() < kSmallestGroup; });
  if (runs && s.model == BaseModel::fixed_point) *runs = groups.size();
  for (const Group& g : groups) {
    try {
      if (g.key.method.name == "taylor" && tangent_sweep(s)) {
        run_taylor_tangent_group(s, g, out);
      } else if (g.key.method.name == "taylor") {
        run_taylor_group(s, g, out);
      } else if (tangent_sweep(s)) {
        run_tangent_group(s, g, out);
      } else {
        run_group(s, g, out);
      }
    } catch (const std::exception&) {  // the same error at every point: reported point by point
      for (const Member& p : g.members) out[p.slot].reset();
    }
  }
  if (in_ensemble) {
    *in_ensemble = static_cast<std::size_t>(std::count_if(
        out.begin(), out.end(), [](const std::optional<PointResult>& r) { return r.has_value(); }));
  }
  std::vector<PointResult> results;
  results.reserve(indices.size());
  for (std::size_t slot = 0; slot < indices.size(); ++slot) {
    results.push_back(out[slot] ? std::move(*out[slot]) : evaluate_point_safely(s, indices[slot]));
  }
  return results;
}

}  // namespace newtop::sweep
