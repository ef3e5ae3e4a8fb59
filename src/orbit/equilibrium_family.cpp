// Relative equilibria of the orbit model along a path in the principal moments
// (docs/continuation.md §4; the linearisation of docs/orbit.md §7–§8).

#include <cmath>

#include "newtop/orbit/orbit_families.hpp"
#include "newtop/orbit/orbit_stability.hpp"

namespace newtop {

namespace {

/// The characteristic polynomial in s (constant term first, odd terms zero) as the cubic
/// σ³ + a2 σ² + a1 σ + a0 in σ = s²: (a0, a1, a2).
Eigen::Vector3d sigma_cubic(const Eigen::Matrix<double, 7, 1>& c) { return {c[0], c[2], c[4]}; }

/// The discriminant of σ³ + a2 σ² + a1 σ + a0.
double discriminant(const Eigen::Vector3d& a) {
  const double a0 = a[0], a1 = a[1], a2 = a[2];
  return 18 * a2 * a1 * a0 - 4 * a2 * a2 * a2 * a0 + a2 * a2 * a1 * a1 - 4 * a1 * a1 * a1 -
         27 * a0 * a0;
}

/// The double root of the cubic where its discriminant vanishes: with (σ − r)²(σ − q),
/// 9a0 − a1 a2 = 2r(r − q)² and a2² − 3a1 = (r − q)².
double double_root(const Eigen::Vector3d& a) {
  return (9 * a[0] - a[1] * a[2]) / (2 * (a[2] * a[2] - 3 * a[1]));
}

}  // namespace

Family equilibrium_family(const Vec3& inertia, int radial, int normal, int index, double p0,
                          double p1, const ContinuationSettings& settings) {
  if (radial < 0 || radial > 2 || normal < 0 || normal > 2 || radial == normal || index < 0 ||
      index > 2) {
    throw InputError(
        "equilibrium family: expected two different principal axes (0, 1, 2) for "
        "the radius and the orbit normal and a moment index 0, 1, 2");
  }
  auto model_at = [inertia, index](double p) {
    Vec3 I = inertia;
    I[index] = p;
    return CircularOrbitModel(Body::from_principal(I, 1.0, Vec3::Zero()),
                              CircularOrbit::from_rate(1.0));
  };
  model_at(p0);  // both ends form a body (the admissible moments are an interval)
  model_at(p1);
  const Vec3 gamma = Vec3::Unit(radial), n = Vec3::Unit(normal);
  ContinuationProblem pr;
  pr.unknowns = 0;
  pr.evaluate = [=](const Eigen::VectorXd&, double p) {
    const CircularOrbitModel model = model_at(p);
    const RelativeSpectrum sp =
        relative_equilibrium_stability(model, relative_rest_state(model, gamma, n));
    const Eigen::Vector3d a = sigma_cubic(sp.characteristic);
    FamilyPoint pt;
    pt.values = model.body().inertia();
    pt.multipliers = sp.eigenvalues;
    pt.stability = to_string(sp.verdict);
    pt.tests = {a[0], discriminant(a)};
    return pt;
  };
  auto imaginary_collision = [=](const FamilyPoint& f) {
    const CircularOrbitModel model = model_at(f.parameter);
    const Eigen::Vector3d a =
        sigma_cubic(characteristic_polynomial(model, relative_rest_state(model, gamma, n)));
    return double_root(a) < 0;
  };
  pr.tests = {{BifurcationType::branch_point, {}}, {BifurcationType::krein, imaginary_collision}};
  return continue_family(pr, Eigen::VectorXd(), p0, p1, settings);
}

}  // namespace newtop
