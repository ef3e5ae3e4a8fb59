// Sweeps over orbit scenarios (docs/sweep.md, "Orbit scenarios"): the point's orbit scenario, the
// quantities that apply to a satellite on a circular or elliptic orbit (final_state, drift, the
// DeBra–Delp class of the LVLH rest orientation, the synchronous odd solution of Beletsky's
// equation), and the refusal of those that do not, naming the quantity and the model.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/orbit_settings.hpp"
#include "newtop/orbit/debra_delp.hpp"
#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "newtop/orbit/orbit_section.hpp"
#include "newtop/orbit/spin_orbit.hpp"
#include "sweep_points.hpp"

namespace newtop::sweep {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

OrbitRun run_orbit(const SweepFile& s, const io::OrbitScenario& sc) {
  const MethodSettings method = io::resolve_method(sc, s.integrate);
  const double t0 = sc.integrate.t0, t1 = io::resolve_t_end(sc, s.integrate);
  const std::int64_t max_steps = sc.integrate.max_steps.value_or(100'000'000);
  OrbitRun r;
  if (const auto* c = std::get_if<CircularOrbit>(&sc.orbit)) {
    const CircularOrbitModel model(sc.body, *c);
    const double h0 = jacobi_integral(model, sc.initial);
    r.drift.observe(sc.initial, &h0);
    r.outcome = run_orbit_method(method, model, sc.initial, t0, t1, max_steps,
                                 [&](double, const OrbitState& x) {
                                   const double h = jacobi_integral(model, x);
                                   r.drift.observe(x, &h);
                                 });
    r.t = r.outcome.t;
    return r;
  }
  const auto& e = std::get<EllipticOrbit>(sc.orbit);
  const double nu0 = e.true_anomaly0, nu1 = true_anomaly_at(e, t1 - t0);
  r.drift.observe(sc.initial, nullptr);
  r.outcome =
      run_orbit_method(method, EllipticOrbitModel(sc.body, e), sc.initial, nu0, nu1, max_steps,
                       [&](double, const OrbitState& x) { r.drift.observe(x, nullptr); });
  r.t = r.outcome.t == nu1 ? t1 : t0 + elapsed_time(e, nu0, r.outcome.t);
  return r;
}

/// The moments of the roll, pitch and yaw axes (the principal axes 1, 2, 3: at rest in LVLH with
/// C(body←LVLH) = I, docs/orbit.md §11) and the ratios of docs/orbit.md §8.
std::pair<double, double> debra_delp_ratios(const Body& body) {
  if (body.gyrostat() != Vec3::Zero()) {
    throw InputError("debra_delp: expected a body without gyrostatic moment, found gyrostat = " +
                     format_vector(body.gyrostat()));
  }
  const Vec3& I = body.inertia();
  return {(I[1] - I[2]) / I[0], (I[1] - I[0]) / I[2]};
}

void add_debra_delp(const io::OrbitScenario& sc, std::vector<double>& v) {
  const auto [k_R, k_Y] = debra_delp_ratios(sc.body);
  const DebraDelpPoint p = debra_delp_point(k_R, k_Y);
  auto code = [](DebraDelpRegion r) {
    return r == DebraDelpRegion::lagrange ? 2.0 : r == DebraDelpRegion::debra_delp ? 1.0 : 0.0;
  };
  // The rest orientation: γ along body z (yaw), n along body y (pitch); frequencies in units of ω0.
  OrbitState rest;
  rest.gamma = Vec3::UnitZ();
  rest.normal = Vec3::UnitY();
  const auto modes = libration_modes(sc.body, rest, 1.0);
  v.insert(v.end(), {k_R, k_Y, code(p.computed), code(p.closed_form), p.boundary ? 1.0 : 0.0,
                     p.max_real_part});
  for (const LibrationMode& m : modes) v.push_back(m.oscillating ? m.frequency : kNaN);
}

/// Beletsky's problem of the point (the pitch axis found from the state, as `newtop libration`).
PitchProblem point_pitch_problem(const io::OrbitScenario& sc) {
  const PitchFrame f = pitch_frame(sc.body, sc.initial);
  return pitch_problem(f.body, std::get<EllipticOrbit>(sc.orbit));
}

void add_synchronous_odd(const io::OrbitScenario& sc, std::vector<double>& v) {
  const PitchProblem p = point_pitch_problem(sc);
  const std::optional<double> dtheta0 = synchronous_odd_rate(p.eccentricity, p.k);
  if (!dtheta0) {
    v.insert(v.end(), {p.k, 0.0, kNaN, kNaN, kNaN});
    return;
  }
  const PeriodicSolution odd = periodic_solution_at(p, resonance(1, 1), 0.0, *dtheta0);
  const double stable = odd.stability == FloquetStability::stable     ? 1.0
                        : odd.stability == FloquetStability::unstable ? 0.0
                                                                      : kNaN;
  v.insert(v.end(), {p.k, 1.0, odd.dtheta0, odd.monodromy.trace(), stable});
}

/// The tangent run of `newtop chaos` on an orbit (docs/orbit.md §13): an embedded pair with its
/// tolerance (a splitting is refused by check_orbit_chaos_settings, naming `method`).
OrbitChaosSettings orbit_chaos_settings(const SweepFile& s, const io::OrbitScenario& sc) {
  OrbitChaosSettings c;
  c.method = io::resolve_method(sc, s.integrate);
  c.t0 = sc.integrate.t0;
  c.t1 = io::resolve_t_end(sc, s.integrate);
  c.max_steps = sc.integrate.max_steps.value_or(c.max_steps);
  return c;
}

OrbitChaosResult run_orbit_chaos(const SweepFile& s, const io::OrbitScenario& sc) {
  const OrbitChaosSettings c = orbit_chaos_settings(s, sc);
  if (const auto* circ = std::get_if<CircularOrbit>(&sc.orbit)) {
    return orbit_chaos(CircularOrbitModel(sc.body, *circ), sc.initial, c);
  }
  return orbit_chaos(EllipticOrbitModel(sc.body, std::get<EllipticOrbit>(sc.orbit)), sc.initial, c);
}

/// The values of the quantity q (drift or final_state) of a run.
void add_run_values(const SweepFile& s, const std::string& q, const io::OrbitScenario& sc,
                    const OrbitRun& run, std::vector<double>& v) {
  if (q == "drift") {
    const OrbitSectionDrift& d = run.drift;
    if (s.model == BaseModel::circular_orbit) v.push_back(d.jacobi);
    v.insert(v.end(), {d.gamma_gamma, d.normal_normal, d.gamma_normal});
  } else if (q == "final_state") {
    const OrbitState& x = run.outcome.state;
    const Vec3 w = omega(sc.body, x);
    v.insert(v.end(), {run.t, w.x(), w.y(), w.z(), x.gamma.x(), x.gamma.y(), x.gamma.z(),
                       x.normal.x(), x.normal.y(), x.normal.z()});
  }
}

}  // namespace

PointResult orbit_run_result(const SweepFile& s, const io::OrbitScenario& sc, const OrbitRun& run) {
  if (run.outcome.status != Status::finished) {
    return {std::string(to_string(run.outcome.status)), {}};
  }
  PointResult r{"ok", {}};
  for (const std::string& q : s.quantities) add_run_values(s, q, sc, run, r.values);
  return r;
}

io::OrbitScenario orbit_point_scenario(const SweepFile& s, std::size_t index) {
  if (s.model == BaseModel::fixed_point) {
    throw InputError(s.source + ": the base scenario is not an orbit scenario (point_scenario)");
  }
  const std::string text = set_keys(s, index);
  try {
    return io::parse_orbit_scenario(text, s.base_source);
  } catch (const InputError& e) {
    rethrow_for_point(s, index, e);
  }
}

std::vector<std::string> orbit_quantity_columns(const SweepFile& s) {
  std::vector<std::string> c;
  for (const std::string& q : s.quantities) {
    if (q == "drift") {
      if (s.model == BaseModel::circular_orbit) c.push_back("drift_jacobi");
      c.insert(c.end(), {"drift_geometric", "drift_normal_normal", "drift_gamma_normal"});
    }
    if (q == "final_state") {
      c.insert(c.end(),
               {"t", "p", "q", "r", "gamma1", "gamma2", "gamma3", "normal1", "normal2", "normal3"});
    }
    if (q == "debra_delp") {
      c.insert(c.end(),
               {"k_R", "k_Y", "stability_class", "closed_form_class", "boundary", "max_real_part",
                "pitch_frequency", "roll_yaw_frequency1", "roll_yaw_frequency2"});
    }
    if (q == "synchronous_odd") {
      c.insert(c.end(), {"k", "odd_found", "odd_dtheta0", "odd_trace", "odd_stable"});
    }
    if (q == "megno") c.push_back("megno");
    if (q == "lyapunov_max") c.push_back("lyapunov_max");
  }
  return c;
}

void check_model(const SweepFile& s) {
  const bool orbit = s.model != BaseModel::fixed_point;
  for (const std::string& q : s.quantities) {
    std::string why;
    if (orbit && (q == "stability" || q == "equilibria")) {
      why = q == "stability" ? "use debra_delp, or newtop stability --equilibrium K"
                             : "use newtop equilibria on the scenario";
    } else if (!orbit && (q == "debra_delp" || q == "synchronous_odd")) {
      why = "it needs an orbit scenario ([orbit])";
    } else if (q == "debra_delp" && s.model != BaseModel::circular_orbit) {
      why = "the LVLH rest orientation is an equilibrium on a circular orbit only";
    } else if (q == "synchronous_odd" && s.model != BaseModel::elliptic_orbit) {
      why = "Beletsky's equation in the true anomaly needs kind = \"elliptic\" (e = 0 allowed)";
    }
    if (!why.empty()) {
      throw InputError(s.source + ": quantities: '" + q + "' does not apply to the " +
                       to_string(s.model) + " model of " + s.base_source + " (" + why + ")");
    }
  }
  if (orbit && s.level) {
    throw InputError(s.source + ": [level] does not apply to the " + to_string(s.model) +
                     " model of " + s.base_source + " (the energy level of a fixed point)");
  }
  for (const Axis& a : s.axes) {
    if (!orbit && (a.key == "body.k_R" || a.key == "body.k_Y")) {
      throw InputError(s.source + ": [[axes]] key '" + a.key +
                       "': an inertia ratio of a satellite on an orbit (docs/orbit.md §8), found "
                       "the fixed point model of " +
                       s.base_source);
    }
  }
}

void check_orbit_point(const SweepFile& s, const io::OrbitScenario& sc) {
  if (wants(s, "drift") || wants(s, "final_state")) {
    io::resolve_method(sc, s.integrate);
    io::resolve_t_end(sc, s.integrate);
  }
  if (wants(s, "debra_delp")) {
    const auto [k_R, k_Y] = debra_delp_ratios(sc.body);
    inertia_from_ratios(k_R, k_Y);  // a body on the edge of the triangle inequality: |k| = 1
  }
  if (wants(s, "synchronous_odd")) point_pitch_problem(sc);
  if (wants(s, "megno") || wants(s, "lyapunov_max")) {
    check_orbit_chaos_settings(orbit_chaos_settings(s, sc));
  }
}

PointResult evaluate_orbit_point(const SweepFile& s, std::size_t index) {
  const io::OrbitScenario sc = orbit_point_scenario(s, index);
  std::optional<OrbitRun> run;
  if (wants(s, "drift") || wants(s, "final_state")) {
    run = run_orbit(s, sc);
    if (run->outcome.status != Status::finished) {
      return {std::string(to_string(run->outcome.status)), {}};
    }
  }
  std::optional<OrbitChaosResult> chaos;
  if (wants(s, "megno") || wants(s, "lyapunov_max")) {  // one tangent run for both
    chaos = run_orbit_chaos(s, sc);
    if (chaos->outcome.status != Status::finished) {
      return {std::string(to_string(chaos->outcome.status)), {}};
    }
  }
  PointResult r{"ok", {}};
  for (const std::string& q : s.quantities) {
    if (q == "megno") {
      r.values.push_back(chaos->indicators.megno);
    } else if (q == "lyapunov_max") {
      r.values.push_back(chaos->indicators.lyapunov_max);
    } else if (q == "drift" || q == "final_state") {
      add_run_values(s, q, sc, *run, r.values);
    } else if (q == "debra_delp") {
      add_debra_delp(sc, r.values);
    } else if (q == "synchronous_odd") {
      add_synchronous_odd(sc, r.values);
    }
  }
  return r;
}

}  // namespace newtop::sweep
