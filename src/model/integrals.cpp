#include "newtop/model/integrals.hpp"

#include <algorithm>
#include <cmath>

namespace newtop {
namespace {

bool negligible(double x, double scale) { return std::abs(x) <= kConditionTolerance * scale; }

// Radius of gyration sqrt(max I / M): the length against which a centre-of-mass offset is
// negligible.
double gyration_radius(const Body& b) {
  return std::sqrt(b.inertia().maxCoeff() / std::max(b.mass(), 1e-300));
}

}  // namespace

double brun(const QuadraticModel& model, const State& s) {
  const Vec3& I = model.body.inertia();
  const Vec3 Iw = s.m - model.body.gyrostat();  // I ω
  const double ABC = I.prod();
  return Iw.squaredNorm() - model.field.lambda_ * ABC * s.gamma.dot(s.gamma.cwiseQuotient(I));
}

double lagrange(const QuadraticModel& /*model*/, const State& s) { return s.m.z(); }

bool brun_holds(const QuadraticModel& model) {
  const Body& b = model.body;
  const bool no_linear = model.field.g == 0.0 || b.mass() == 0.0 ||
                         negligible(b.center_of_mass().norm(), gyration_radius(b));
  return no_linear && b.gyrostat().isZero(0.0);
}

bool lagrange_holds(const QuadraticModel& model) {
  const Body& b = model.body;
  const double length = gyration_radius(b);
  const bool symmetric = negligible(b.A() - b.B(), b.A());
  const bool on_axis =
      model.field.g == 0.0 || b.mass() == 0.0 ||
      (negligible(b.center_of_mass().x(), length) && negligible(b.center_of_mass().y(), length));
  const bool rotor_on_axis = b.gyrostat().x() == 0.0 && b.gyrostat().y() == 0.0;
  return symmetric && on_axis && rotor_on_axis;
}

std::vector<std::string> conserved_integrals(const QuadraticModel& model) {
  std::vector<std::string> names{"energy", "area", "geometric"};
  if (brun_holds(model)) names.emplace_back("brun");
  if (lagrange_holds(model)) names.emplace_back("lagrange");
  return names;
}

IntegralValues integrals(const QuadraticModel& model, const State& s) {
  IntegralValues v{energy(model, s), area(s), geometric(s), std::nullopt, std::nullopt};
  if (brun_holds(model)) v.brun = brun(model, s);
  if (lagrange_holds(model)) v.lagrange = lagrange(model, s);
  return v;
}

std::vector<std::string> conserved_integrals(const Model& model) {
  if (model.kind() == FieldKind::quadratic) return conserved_integrals(model.quadratic());
  return {"energy", "area", "geometric"};
}

void IntegralsDrift::observe(const IntegralValues& v) {
  if (!started) {
    started = true;
    initial = v;
    max_drift = v;
    max_drift.energy = max_drift.area = max_drift.geometric = 0.0;
    if (max_drift.brun) max_drift.brun = 0.0;
    if (max_drift.lagrange) max_drift.lagrange = 0.0;
    return;
  }
  auto upd = [](double& m, double a, double b) { m = std::max(m, std::abs(a - b)); };
  upd(max_drift.energy, v.energy, initial.energy);
  upd(max_drift.area, v.area, initial.area);
  upd(max_drift.geometric, v.geometric, initial.geometric);
  if (v.brun && initial.brun) upd(*max_drift.brun, *v.brun, *initial.brun);
  if (v.lagrange && initial.lagrange) upd(*max_drift.lagrange, *v.lagrange, *initial.lagrange);
}

void IntegralsDrift::observe(const Model& model, const State& s) {
  observe(integrals(model, s));
  max_m = std::max(max_m, s.m.norm());
}

void IntegralsDrift::merge(const IntegralsDrift& other) {
  if (!other.started) return;
  if (!started) {
    *this = other;
    return;
  }
  auto upd = [](double& m, double v) { m = std::max(m, v); };
  upd(max_drift.energy, other.max_drift.energy);
  upd(max_drift.area, other.max_drift.area);
  upd(max_drift.geometric, other.max_drift.geometric);
  upd(max_m, other.max_m);
  if (max_drift.brun && other.max_drift.brun) upd(*max_drift.brun, *other.max_drift.brun);
  if (max_drift.lagrange && other.max_drift.lagrange) {
    upd(*max_drift.lagrange, *other.max_drift.lagrange);
  }
}

CasimirDrift casimir_drift(const IntegralsDrift& drift) {
  CasimirDrift c;
  c.geometric = drift.max_drift.geometric / drift.initial.geometric;
  c.area = drift.max_m > 0 ? drift.max_drift.area / drift.max_m : 0.0;
  return c;
}

}  // namespace newtop
