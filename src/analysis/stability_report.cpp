#include "newtop/analysis/stability_report.hpp"

#include <algorithm>
#include <string>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/model/state_checks.hpp"

namespace newtop {
namespace {

const char kAxisNames[] = "xyz";

/// Why Beletsky's formula does not give Ω* for this spin: what it needs, and what the axis is.
std::string formula_note(const QuadraticModel& m, int axis, bool no_offset) {
  const std::string name(1, kAxisNames[axis]);
  std::string why;
  if (!no_offset)
    why = "M g r0 = " + format_number(m.body.mass() * m.field.g * m.body.center_of_mass().norm());
  const AxisClass c = axis_class(m.body, axis);
  if (c != AxisClass::largest) {
    if (!why.empty()) why += ", ";
    why += name + " is the " + to_string(c) + "-moment axis";
  }
  if (!(m.field.lambda_ > 0)) {
    if (!why.empty()) why += ", ";
    why += "lambda = " + format_number(m.field.lambda_);
  }
  if (why.empty()) why = "the spin is stable for every Omega";
  return "not applicable: the formula needs the largest-moment axis, r0 = 0 and lambda > 0; " + why;
}

}  // namespace

std::optional<int> spin_axis_of(const QuadraticModel& model, const State& s) {
  const Vec3 w = omega(model.body, s);
  const Vec3 b = model.body.mass() * model.field.g * model.body.center_of_mass();
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = Vec3::Unit(i);
    if ((s.gamma - e).norm() <= kFixedPointTolerance &&
        w.cross(e).norm() <= kFixedPointTolerance * std::max(w.norm(), 1.0) &&
        b.cross(e).norm() <= kFixedPointTolerance * b.norm()) {
      return i;
    }
  }
  return std::nullopt;
}

StabilityReport stability_report(const Model& model, const State& state,
                                 const PolishedFixedPoint& polish, std::optional<int> axis) {
  StabilityReport r;
  r.state = state;
  r.axis = axis;
  r.polish = polish;
  r.spectrum = linear_stability(model, r.state);
  r.residual = fixed_point_residual(model, r.state);
  if (axis) {
    const QuadraticModel& m = model.quadratic();
    const bool no_offset = m.body.mass() * m.field.g * m.body.center_of_mass().norm() == 0.0;
    if (no_offset) r.threshold_formula = beletsky_threshold(m.body, m.field.lambda_, *axis);
    r.threshold_numeric = numeric_threshold(m, *axis);
    if (!r.threshold_formula) r.formula_note = formula_note(m, *axis, no_offset);
  }
  return r;
}

StabilityReport stability_of_axis(const Model& model, int axis, double Omega) {
  if (axis < 0 || axis > 2) {
    throw InputError("axis: expected 0, 1 or 2 (x, y, z), found " + std::to_string(axis));
  }
  if (model.kind() != FieldKind::quadratic) {
    throw InputError(std::string("axis: spins about principal axes and their thresholds need the "
                                 "quadratic field, found the ") +
                     to_string(model.kind()) + " field");
  }
  const State s = principal_spin(model.body(), axis, Omega);
  const double res = fixed_point_residual(model, s);
  if (!(res <= kFixedPointTolerance)) {
    throw InputError(std::string("axis ") + kAxisNames[axis] +
                     ": expected a permanent rotation, found residual " + format_number(res) +
                     " of d(m, gamma)/dt (M g r0 is not along the axis)");
  }
  return stability_report(model, s, polish_fixed_point(model, s), axis);
}

StabilityReport stability_of_equilibrium(const Model& model, int k) {
  const EquilibriumSet set = find_equilibria(model);
  const int count = static_cast<int>(set.equilibria.size());
  using Reason = StabilityChoiceError::Reason;
  if (count == 0) {
    StabilityChoiceError e(
        Reason::no_equilibrium,
        std::string("equilibrium: the model has no isolated equilibrium") +
            (set.every_orientation ? " (every orientation is an equilibrium)" : ""));
    e.every_orientation = set.every_orientation;
    throw e;
  }
  if (k < 1 || k > count) {
    StabilityChoiceError e(Reason::equilibrium_index,
                           "equilibrium: expected 1 to " + std::to_string(count) +
                               " (the equilibria of find_equilibria), found " + std::to_string(k));
    e.count = count;
    throw e;
  }
  return stability_of_state(
      model, state_from_omega(model.body(), Vec3::Zero(), set.equilibria[k - 1].gamma));
}

std::string polish_failure(const PolishedFixedPoint& p) {
  return "found residual " + format_number(p.residual_given) + " of d(m, gamma)/dt, and " +
         (p.iterations == 0 ? std::string("Newton's method finds no fixed point near it")
          : p.correction > kPolishRadius
              ? "the fixed point Newton's method finds is " + format_number(p.correction) +
                    " away (more than " + format_number(kPolishRadius) + ")"
              : "Newton's method stops at residual " + format_number(p.residual));
}

StabilityReport stability_of_state(const Model& model, const State& s) {
  validate(s);
  const PolishedFixedPoint p = polish_fixed_point(model, s);
  if (!p.converged) {
    StabilityChoiceError e(
        StabilityChoiceError::Reason::not_fixed_point,
        "state: expected an equilibrium or a permanent rotation (to three digits or more), " +
            polish_failure(p));
    e.polish = p;
    throw e;
  }
  // The spin families about principal axes (and their thresholds) are the quadratic field's.
  const std::optional<int> axis = model.kind() == FieldKind::quadratic
                                      ? spin_axis_of(model.quadratic(), p.state)
                                      : std::nullopt;
  return stability_report(model, p.state, p, axis);
}

}  // namespace newtop
