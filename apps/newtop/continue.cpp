// newtop continue SCENARIO --family KIND --parameter KEY --range A:B: a family of periodic
// solutions, relative equilibria or permanent rotations continued by pseudo-arclength in one
// scenario key, with its folds, flips, branch points and Krein collisions located
// (docs/continuation.md).

#include "continue.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>

#include "command.hpp"
#include "newtop/analysis/rotation_family.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/orbit/orbit_families.hpp"
#include "newtop/orbit/orbit_stability.hpp"

namespace newtop::app {
namespace {

constexpr double kPi = std::numbers::pi;

std::pair<double, double> parse_range(const std::string& text) {
  const auto ab = io::read_colon_values<double, double>(text);
  if (!ab || !std::isfinite(std::get<0>(*ab)) || !std::isfinite(std::get<1>(*ab)) ||
      std::get<0>(*ab) == std::get<1>(*ab)) {
    throw InputError("--range: expected A:B, two different finite numbers, found '" + text + "'");
  }
  return {std::get<0>(*ab), std::get<1>(*ab)};
}

SpinOrbitResonance parse_resonance(const std::string& text) {
  const auto pq = io::read_colon_values<int, int>(text);
  if (!pq) throw InputError("--resonance: expected P:Q (integers), found '" + text + "'");
  try {
    return resonance(std::get<0>(*pq), std::get<1>(*pq));
  } catch (const InputError& e) {
    throw InputError(std::string("--resonance: ") + e.what());
  }
}

double parse_line(const std::string& text) {
  if (text == "pi/2") return kPi / 2;
  std::istringstream is(text);
  double v = 1.0;
  std::string rest;
  if ((is >> v) && !(is >> rest)) {
    if (v == 0.0) return 0.0;
    if (std::abs(v - kPi / 2) < 1e-12) return kPi / 2;
  }
  throw InputError(
      "--line: expected the reversibility line theta(0) = 0 or pi/2 (1.5707963267948966), found '" +
      text + "'");
}

/// `body.inertia[i]` → i; nullopt for another key.
std::optional<int> inertia_index(const std::string& key) {
  for (int i = 0; i < 3; ++i)
    if (key == "body.inertia[" + std::to_string(i) + "]") return i;
  return std::nullopt;
}

EllipticOrbit pitch_orbit(const io::OrbitScenario& sc) {
  if (const auto* e = std::get_if<EllipticOrbit>(&sc.orbit)) return *e;
  const auto& c = std::get<CircularOrbit>(sc.orbit);
  if (!(c.rate > 0) || c.lambda_ != 3.0 * c.rate * c.rate) {
    throw InputError(sc.source +
                     ": [orbit]: expected a Kepler orbit (lambda = 3 rate^2), found "
                     "rate " +
                     format_number(c.rate) + " and lambda " + format_number(c.lambda_));
  }
  return EllipticOrbit::from_mean_motion(c.rate, 0.0, 0.0);
}

/// kEccentricityKey for orbit.eccentricity, i for body.inertia[i], nullopt otherwise.
std::optional<int> pitch_key(const std::string& key) {
  if (key == "orbit.eccentricity") return kEccentricityKey;
  return inertia_index(key);
}

/// The second key, its range about the scenario's value q0 and the plane of (e, k) they span,
/// checked before any work.
ResonanceSecondAxis check_second(const ContinueArgs& a, const Vec3& inertia, double e, double p0) {
  const auto q_key = pitch_key(*a.second);
  if (!q_key || *q_key == *pitch_key(a.parameter)) {
    throw InputError(
        "--second: expected orbit.eccentricity or body.inertia[0..2] other than "
        "--parameter, found '" +
        *a.second + "'");
  }
  const auto [c, d] = parse_range(*a.second_range);
  const double q0 = *q_key == kEccentricityKey ? e : inertia[*q_key];
  if (q0 < std::min(c, d) || q0 > std::max(c, d)) {
    throw InputError("--second-range: expected a range about the scenario's " + *a.second + " = " +
                     format_number(q0) + ", found " + *a.second_range);
  }
  ResonanceSecondAxis s{pitch_plane_path(inertia, e, *pitch_key(a.parameter), *q_key), c, d, q0};
  for (const double q : {c, d}) {
    try {
      s.path(p0, q);
    } catch (const InputError& err) {
      throw InputError("--second-range: " + *a.second + " = " + format_number(q) + ": " +
                       err.what());
    }
  }
  return s;
}

Run run_resonance(const ContinueArgs& a, double p0, double p1) {
  const io::OrbitScenario sc = io::load_orbit_scenario(a.scenario);
  const EllipticOrbit orbit = pitch_orbit(sc);
  const PitchProblem base = pitch_problem(sc.body, orbit);  // no gyrostat, r0 = 0
  const SpinOrbitResonance r = parse_resonance(a.resonance.value_or("1:1"));
  const double line = a.line ? parse_line(*a.line) : 0.0;
  PitchPath path;
  if (a.parameter == "orbit.eccentricity") {
    path = eccentricity_path(base.k);
  } else if (const auto i = inertia_index(a.parameter)) {
    path = inertia_path(sc.body.inertia(), *i, base.eccentricity);
  } else {
    refuse_key(a, "orbit.eccentricity or body.inertia[0..2]");
  }
  for (const double p : {p0, p1}) {
    try {
      path(p);
    } catch (const InputError& e) {
      throw InputError("--range: " + a.parameter + " = " + format_number(p) + ": " + e.what());
    }
  }
  ResonanceRequest request{path, p0, p1, r, line, std::nullopt, a.switch_branches};
  if (a.second) request.second = check_second(a, sc.body.inertia(), base.eccentricity, p0);
  ResonanceContinuation c = continue_resonance(request);
  return {
      std::move(c.family), {"theta0", "dtheta0"}, std::move(c.boundaries), std::move(c.branches)};
}

Run run_rotation(const ContinueArgs& a, double p0, double p1) {
  if (a.parameter != "stability.omega") refuse_key(a, "stability.omega");
  const io::Scenario sc = io::load_scenario(a.scenario);
  if (sc.model.kind() != FieldKind::quadratic) {
    throw InputError(sc.source + ": [field]: expected the quadratic field for --family rotation");
  }
  const QuadraticModel& m = sc.model.quadratic();
  return {rotation_family(m, largest_axis(m.body), p0, p1), {"omega"}, {}, {}};
}

Run run_equilibrium(const ContinueArgs& a, double p0, double p1) {
  if (!io::is_orbit_scenario(a.scenario)) return run_rest(a, p0, p1);
  const auto i = inertia_index(a.parameter);
  if (!i) refuse_key(a, "body.inertia[0..2]");
  const io::OrbitScenario sc = io::load_orbit_scenario(a.scenario);
  if (!sc.circular() || sc.body.gyrostat() != Vec3::Zero()) {
    throw InputError(sc.source +
                     ": expected a circular orbit and no gyrostat for --family "
                     "equilibrium");
  }
  const CircularOrbitModel model(sc.body, std::get<CircularOrbit>(sc.orbit));
  int radial = 0, normal = 0;
  sc.initial.gamma.cwiseAbs().maxCoeff(&radial);
  sc.initial.normal.cwiseAbs().maxCoeff(&normal);
  if (std::abs(sc.initial.gamma[radial]) < 1 - 1e-9 ||
      std::abs(sc.initial.normal[normal]) < 1 - 1e-9 ||
      !(fixed_point_residual(model, sc.initial) <= kRelativeEquilibriumTolerance)) {
    throw InputError(sc.source +
                     ": [initial]: expected a relative equilibrium with the radius and "
                     "the orbit normal along principal axes (at rest in the orbital frame)");
  }
  return {
      equilibrium_family(sc.body.inertia(), radial, normal, *i, p0, p1), {"A", "B", "C"}, {}, {}};
}

/// The options that apply only to some families, checked before any work.
void check_options(const ContinueArgs& a) {
  if (a.second.has_value() != a.second_range.has_value()) {
    throw InputError(std::string("--second and --second-range: expected both, found only ") +
                     (a.second ? "--second" : "--second-range"));
  }
  if (a.second && a.family != "resonance") {
    throw InputError("--second: applies only to --family resonance, found --family " + a.family);
  }
  if (a.switch_branches && a.family != "resonance") {
    throw InputError("--switch: applies only to --family resonance, found --family " + a.family);
  }
  if (a.switch_branches && a.second) {
    throw InputError("--switch: expected one of --switch and --second, found both");
  }
  if (a.mode && a.family != "periodic") {
    throw InputError("--mode: applies only to --family periodic, found --family " + a.family);
  }
  if (a.family != "resonance" && (a.resonance || a.line)) {
    throw InputError(std::string(a.resonance ? "--resonance" : "--line") +
                     ": applies only to --family resonance, found --family " + a.family);
  }
}

int run(const ContinueArgs& a) {
  check_options(a);
  const auto [p0, p1] = parse_range(a.range);
  // The output file is created before any work (and removed if the work throws).
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) {
    const std::string inputs[] = {a.scenario};
    file = std::make_unique<io::AtomicFile>(*a.out, inputs);
  }
  Run r;
  if (a.family == "resonance") {
    r = run_resonance(a, p0, p1);
  } else if (a.family == "rotation") {
    r = run_rotation(a, p0, p1);
  } else if (a.family == "equilibrium") {
    r = run_equilibrium(a, p0, p1);
  } else if (a.family == "periodic") {
    r = run_periodic(a, p0, p1);
  } else {
    throw InputError("--family: expected resonance, periodic, equilibrium or rotation, found '" +
                     a.family + "'");
  }
  return report(a, r, p0, p1, file.get());
}

const RegisterCommand reg_continue{Command{
    "continue",
    "Continue a family (spin-orbit resonance, Lyapunov orbits, equilibrium, rotation) in one "
    "parameter "
    "and locate its bifurcations",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<ContinueArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      sub.add_option("--family", a->family, "resonance, periodic, equilibrium or rotation")
          ->required();
      sub.add_option("--parameter", a->parameter,
                     "scenario key: orbit.eccentricity, body.inertia[i], stability.omega")
          ->required();
      sub.add_option("--range", a->range, "A:B, the parameter's first and last value")->required();
      sub.add_option("--resonance", a->resonance, "P:Q spin:orbit (resonance; default 1:1)");
      sub.add_option("--line", a->line, "theta(0) of the start: 0 or pi/2 (resonance; default 0)");
      sub.add_option("--second", a->second,
                     "second key: each event's locus continued in it (resonance)");
      sub.add_option("--second-range", a->second_range,
                     "C:D, about the scenario's value of the second key");
      sub.add_option(
          "--mode", a->mode,
          "normal mode of the equilibrium: 1 lower, 2 higher frequency (periodic; default 1)");
      sub.add_flag("--switch", a->switch_branches,
                   "continue the branch from each located flip and branch point (resonance)");
      sub.add_option("--out", a->out, "the family as CSV");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace

[[noreturn]] void refuse_key(const ContinueArgs& a, const std::string& allowed) {
  throw InputError("--parameter: expected " + allowed + " for --family " + a.family + ", found '" +
                   a.parameter + "'");
}
}  // namespace newtop::app
