// newtop continue on a fixed-point scenario (docs/continuation.md §4b, §4c): the equilibrium at
// rest continued in a body or field key, and the Lyapunov family of a stable one in the energy.

#include <string>

#include "continue.hpp"
#include "newtop/analysis/lyapunov_family.hpp"
#include "newtop/analysis/rest_family.hpp"
#include "newtop/analysis/stability.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::app {
namespace {

/// The scenario's model (quadratic field) and its initial state, an equilibrium at rest.
const QuadraticModel& rest_model(const io::Scenario& sc, const ContinueArgs& a) {
  if (sc.model.kind() != FieldKind::quadratic) {
    throw InputError(sc.source + ": [field]: expected the quadratic field for --family " +
                     a.family);
  }
  const QuadraticModel& m = sc.model.quadratic();
  if (m.body.gyrostat() != Vec3::Zero() || sc.initial.m != Vec3::Zero() ||
      !(fixed_point_residual(Model(m), sc.initial) <= kFixedPointTolerance)) {
    throw InputError(sc.source +
                     ": [initial]: expected an equilibrium at rest (omega = 0, gamma from "
                     "newtop equilibria) of a body without gyrostat for --family " +
                     a.family);
  }
  return m;
}

}  // namespace

/// The equilibrium at rest of a fixed-point scenario (quadratic field) continued in a body or
/// field key (docs/continuation.md §4b).
Run run_rest(const ContinueArgs& a, double p0, double p1) {
  const io::Scenario sc = io::load_scenario(a.scenario);
  const QuadraticModel& m = rest_model(sc, a);
  QuadraticPath path;
  try {
    path = quadratic_path(m, a.parameter);
  } catch (const InputError&) {
    refuse_key(a,
               "body.inertia[0..2], body.center_of_mass[0..2], body.mass, field.g or field.lambda "
               "(fixed-point scenario)");
  }
  for (const double p : {p0, p1}) {
    try {
      path(p);
    } catch (const InputError& e) {
      throw InputError("--range: " + a.parameter + " = " + format_number(p) + ": " + e.what());
    }
  }
  return {rest_family(path, sc.initial.gamma, p0, p1),
          {"gamma_x", "gamma_y", "gamma_z", "kappa"},
          {},
          {}};
}

/// The Lyapunov family of the scenario's stable equilibrium at rest, in the energy above it
/// (docs/continuation.md §4c).
Run run_periodic(const ContinueArgs& a, double p0, double p1) {
  if (a.parameter != "energy") refuse_key(a, "energy (above the equilibrium's)");
  if (!(p0 > 0) || !(p1 > 0)) {
    throw InputError("--range: expected energies above the equilibrium's, A > 0 and B > 0, found " +
                     a.range);
  }
  const io::Scenario sc = io::load_scenario(a.scenario);
  const QuadraticModel& m = rest_model(sc, a);
  if (!linear_stability(Model(m), sc.initial).linearly_stable) {
    throw InputError(sc.source +
                     ": [initial]: expected a linearly stable equilibrium for "
                     "--family periodic (its normal modes start the families)");
  }
  return {lyapunov_family(m, sc.initial.gamma, a.mode.value_or(1) - 1, p0, p1),
          {"m_x", "m_y", "m_z", "gamma_x", "gamma_y", "gamma_z"},
          {},
          {}};
}

}  // namespace newtop::app
