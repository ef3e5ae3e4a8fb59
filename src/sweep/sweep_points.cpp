// The points of a sweep: the base scenario with the swept keys set, and the quantities computed
// there (docs/sweep.md).

#include "sweep_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/stability.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/integrate/run.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/phase/chaos.hpp"

namespace newtop::sweep {
namespace {

constexpr double kPointNaN = std::numeric_limits<double>::quiet_NaN();

/// The state `stability` analyses: the spin about the axis at Ω, or the scenario's own state
/// polished to a fixed point. Throws InputError when it is not a fixed point.
State stability_state(const io::Scenario& sc, const StabilityOptions& o) {
  if (o.axis) {
    const State x = principal_spin(sc.model.body(), *o.axis, o.omega);
    const double res = fixed_point_residual(sc.model, x);
    if (!(res <= kFixedPointTolerance)) {
      throw InputError(std::string("stability: the spin about ") + "xyz"[*o.axis] +
                       " is not a permanent rotation (residual " + format_number(res) +
                       "; M g r0 is not along the axis)");
    }
    return x;
  }
  const PolishedFixedPoint p = polish_fixed_point(sc.model, sc.initial);
  if (!p.converged) {
    throw InputError("stability: [initial] is not an equilibrium or a permanent rotation " +
                     std::string("(residual ") + format_number(p.residual_given) +
                     "); give [stability] axis");
  }
  return p.state;
}

/// One run of the point's scenario: the final state and the drift of the integrals.
struct RunResult {
  Outcome outcome;
  IntegralsDrift drift;
};

RunResult run(const SweepFile& s, const io::Scenario& sc) {
  const MethodSettings method = io::resolve_method(sc, s.integrate);
  const double t1 = io::resolve_t_end(sc, s.integrate);
  IntegrateOptions options;
  if (sc.integrate.max_steps) options.max_steps = *sc.integrate.max_steps;
  RunResult r;
  r.drift.observe(integrals(sc.model, sc.initial));
  auto observe = [&](double, const State& x) { r.drift.observe(integrals(sc.model, x)); };
  r.outcome = run_method(method, sc.model, sc.initial, sc.integrate.t0, t1, options, observe);
  return r;
}

}  // namespace

std::vector<std::string> quantity_columns(const SweepFile& s) {
  if (s.model != BaseModel::fixed_point) return orbit_quantity_columns(s);
  std::vector<std::string> c;
  for (const std::string& q : s.quantities) {
    if (q == "stability")
      c.insert(c.end(), {"linearly_stable", "lyapunov_stable", "max_real_part"});
    if (q == "drift") c.insert(c.end(), {"drift_energy", "drift_area", "drift_geometric"});
    if (q == "equilibria") c.insert(c.end(), {"equilibria_count", "minima", "saddles", "maxima"});
    if (q == "final_state") c.insert(c.end(), {"t", "p", "q", "r", "gamma1", "gamma2", "gamma3"});
    if (q == "megno") c.push_back("megno");
    if (q == "lyapunov_max") c.push_back("lyapunov_max");
  }
  return c;
}

/// Moves the initial state onto the sweep's energy level: ω_i with ½ I_i ω_i² = h − V(γ) −
/// ½ Σ_{j≠i} I_j ω_j², of the sign asked for (m_i = I_i ω_i + k_i). A level out of reach at this
/// point (the right side negative) leaves a non-finite state: the point is `off_level`.
void move_onto_level(const EnergyLevel& level, io::Scenario& sc) {
  const Body& body = sc.model.body();
  const int i = level.component;
  const Vec3 w = omega(body, sc.initial);
  double rest = level.energy - potential(sc.model, sc.initial.gamma);
  for (int j = 0; j < 3; ++j) {
    if (j != i) rest -= 0.5 * body.inertia()[j] * w[j] * w[j];
  }
  const double wi2 = 2.0 * rest / body.inertia()[i];
  if (!(wi2 >= 0.0)) {
    sc.initial.m.setConstant(kPointNaN);
    return;
  }
  sc.initial.m[i] = body.inertia()[i] * (level.sign * std::sqrt(wi2)) + body.gyrostat()[i];
}

io::Scenario point_scenario(const SweepFile& s, std::size_t index, StabilityOptions* options) {
  if (s.model != BaseModel::fixed_point) {
    throw InputError(s.source + ": the base scenario is an orbit scenario (orbit_point_scenario)");
  }
  const std::vector<double> values = point_values(s, index);
  const std::string text = set_keys(s, index);
  if (options) {
    *options = s.stability;
    for (std::size_t k = 0; k < s.axes.size(); ++k) {
      if (s.axes[k].key == "stability.omega") options->omega = values[k];
    }
  }
  try {
    io::Scenario sc = io::parse_scenario(text, s.base_source);
    if (s.level) move_onto_level(*s.level, sc);
    return sc;
  } catch (const InputError& e) {
    rethrow_for_point(s, index, e);
  }
}

namespace {

/// The orbit sweep's points: each scenario built and each quantity checked to apply.
void check_orbit_points(SweepFile& s) {
  for (std::size_t i = 0, n = point_count(s); i < n; ++i) {
    const io::OrbitScenario sc = orbit_point_scenario(s, i);
    if (i == 0) s.input_files = {s.source, s.base_source};
    try {
      check_orbit_point(s, sc);
    } catch (const InputError& e) {
      throw InputError(s.source + ": " + point_label(s, i) + ": " + e.what());
    }
  }
}

}  // namespace

void check_points(SweepFile& s) {
  if (s.model != BaseModel::fixed_point) return check_orbit_points(s);
  const std::size_t n = point_count(s);
  for (std::size_t i = 0; i < n; ++i) {
    StabilityOptions o;
    const io::Scenario sc = point_scenario(s, i, &o);
    if (i == 0) {
      s.input_files = {s.source};
      s.input_files.insert(s.input_files.end(), sc.input_files.begin(), sc.input_files.end());
    }
    if (s.level && !is_finite(sc.initial)) continue;  // off the level: reported per point
    try {
      if (wants(s, "stability")) stability_state(sc, o);
      if (wants(s, "megno") || wants(s, "lyapunov_max")) {
        phase::check_tangent_method(io::resolve_method(sc, s.integrate));
      }
      if (wants(s, "drift") || wants(s, "final_state") || wants(s, "megno") ||
          wants(s, "lyapunov_max")) {
        io::resolve_method(sc, s.integrate);
        const double t1 = io::resolve_t_end(sc, s.integrate);
        check_time_span(sc.integrate.t0, t1);
        if (t1 == sc.integrate.t0) {  // no run: its drift and indicators would be zeros
          throw InputError(
              "t_end: expected a time different from t0 = " + format_number(sc.integrate.t0) +
              ", found " + format_number(t1) + " (a run of no length)");
        }
      }
    } catch (const InputError& e) {
      throw InputError(s.source + ": " + point_label(s, i) + ": " + e.what());
    }
  }
}

PointResult evaluate_point(const SweepFile& s, std::size_t index) {
  if (s.model != BaseModel::fixed_point) return evaluate_orbit_point(s, index);
  StabilityOptions o;
  const io::Scenario sc = point_scenario(s, index, &o);
  PointResult r{"ok", {}};
  if (s.level && !is_finite(sc.initial)) return {"off_level", {}};
  std::optional<phase::ChaosResult> chaos;
  if (wants(s, "megno") || wants(s, "lyapunov_max")) {  // one tangent run for both (newtop chaos)
    const MethodSettings method = io::resolve_method(sc, s.integrate);
    const double t1 = io::resolve_t_end(sc, s.integrate);
    IntegrateOptions options;
    if (sc.integrate.max_steps) options.max_steps = *sc.integrate.max_steps;
    chaos =
        phase::chaos(sc.model, sc.initial,
                     {.method = method, .t0 = sc.integrate.t0, .t_end = t1, .options = options});
    if (chaos->outcome.status != Status::finished) {
      return {std::string(to_string(chaos->outcome.status)), {}};
    }
  }
  std::optional<RunResult> traj;
  if (wants(s, "drift") || wants(s, "final_state")) {
    traj = run(s, sc);
    if (traj->outcome.status != Status::finished)
      return {std::string(to_string(traj->outcome.status)), {}};
  }
  for (const std::string& q : s.quantities) {
    if (q == "stability") {
      const Spectrum sp = linear_stability(sc.model, stability_state(sc, o));
      r.values.push_back(sp.linearly_stable ? 1.0 : 0.0);
      r.values.push_back(sp.lyapunov_stable ? (*sp.lyapunov_stable ? 1.0 : 0.0) : kPointNaN);
      r.values.push_back(sp.max_real_part);
    } else if (q == "drift") {
      r.values.insert(r.values.end(), {traj->drift.max_drift.energy, traj->drift.max_drift.area,
                                       traj->drift.max_drift.geometric});
    } else if (q == "equilibria") {
      const EquilibriumSet e = find_equilibria(sc.model);
      r.values.insert(r.values.end(),
                      {static_cast<double>(e.equilibria.size()), static_cast<double>(e.minima),
                       static_cast<double>(e.saddles), static_cast<double>(e.maxima)});
    } else if (q == "megno") {
      r.values.push_back(chaos->indicators.megno);
    } else if (q == "lyapunov_max") {
      r.values.push_back(chaos->indicators.lyapunov_max);
    } else if (q == "final_state") {
      const State& x = traj->outcome.state;
      const Vec3 w = omega(sc.model.body(), x);
      r.values.insert(r.values.end(), {traj->outcome.t, w.x(), w.y(), w.z(), x.gamma.x(),
                                       x.gamma.y(), x.gamma.z()});
    }
  }
  return r;
}

}  // namespace newtop::sweep
