// Permanent rotations about a principal axis in the spin rate, with the Krein collision located
// (docs/continuation.md §3).

#include "newtop/analysis/rotation_family.hpp"

#include <Eigen/Dense>

#include "newtop/analysis/stability.hpp"
#include "newtop/analysis/stability_spin.hpp"

namespace newtop {

namespace {

/// (c2, c0) of det(s − J) = s⁴ + c2 s² + c0 for the leaf Jacobian of a Hamiltonian fixed point
/// (tr J = 0 and the odd coefficients vanish): c2 = −tr(J²)/2, c0 = det J.
Eigen::Vector2d even_coefficients(const QuadraticModel& model, int axis, double Omega) {
  const Eigen::Matrix4d j = reduced_jacobian(Model(model), principal_spin(model.body, axis, Omega));
  return {-0.5 * (j * j).trace(), j.determinant()};
}

}  // namespace

int largest_axis(const Body& body) {
  int axis = 0;
  body.inertia().maxCoeff(&axis);
  return axis;
}

Family rotation_family(const QuadraticModel& model, int axis, double omega0, double omega1,
                       const ContinuationSettings& settings) {
  const State s = principal_spin(model.body, axis, 1.0);  // checks the axis
  if (!(fixed_point_residual(Model(model), s) <= kFixedPointTolerance)) {
    throw InputError(std::string("rotation family: the spin about ") + "xyz"[axis] +
                     " is not a fixed point (the centre of mass is off that axis)");
  }
  ContinuationProblem pr;
  pr.unknowns = 0;
  pr.evaluate = [&model, axis](const Eigen::VectorXd&, double Omega) {
    const Spectrum sp = spin_stability(model, axis, Omega);
    const Eigen::Vector2d c = even_coefficients(model, axis, Omega);
    FamilyPoint pt;
    pt.values = Eigen::VectorXd::Constant(1, Omega);
    pt.multipliers = sp.eigenvalues;
    pt.stability = sp.linearly_stable ? "stable" : "unstable";
    pt.tests = {c[0] * c[0] - 4 * c[1]};
    return pt;
  };
  auto imaginary = [&model, axis](const FamilyPoint& f) {
    return even_coefficients(model, axis, f.parameter)[0] > 0;
  };
  pr.tests = {{BifurcationType::krein, imaginary}};
  return continue_family(pr, Eigen::VectorXd(), omega0, omega1, settings);
}

}  // namespace newtop
