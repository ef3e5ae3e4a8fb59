// The equilibria at rest of the fixed-point model continued in a parameter of the body or the
// field (docs/continuation.md §4b).

#include "newtop/analysis/rest_family.hpp"

#include <cmath>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/stability.hpp"

namespace newtop {

namespace {

// An equilibrium given to the digits `newtop equilibria` prints is within this of the family's.
constexpr double kStartTolerance = 1e-6;

/// b + λIγ − κγ and (γ·γ − 1)/2 at u = (γ, κ).
Eigen::VectorXd rest_residual(const QuadraticModel& m, const Eigen::VectorXd& u) {
  const Vec3 g = u.head<3>();
  const Vec3 b = m.body.mass() * m.field.g * m.body.center_of_mass();
  Eigen::VectorXd r(4);
  r.head<3>() = b + m.field.lambda_ * m.body.inertia().cwiseProduct(g) - u[3] * g;
  r[3] = 0.5 * (g.squaredNorm() - 1.0);
  return r;
}

}  // namespace

QuadraticPath quadratic_path(const QuadraticModel& base, const std::string& key) {
  for (int i = 0; i < 3; ++i) {
    const std::string idx = "[" + std::to_string(i) + "]";
    if (key == "body.inertia" + idx || key == "body.center_of_mass" + idx) {
      const bool inertia = key == "body.inertia" + idx;
      return [base, inertia, i](double p) {
        Vec3 I = base.body.inertia(), r0 = base.body.center_of_mass();
        (inertia ? I : r0)[i] = p;
        return QuadraticModel{Body::from_principal(I, base.body.mass(), r0, base.body.gyrostat()),
                              base.field};
      };
    }
  }
  if (key == "body.mass") {
    return [base](double p) {
      return QuadraticModel{Body::from_principal(base.body.inertia(), p, base.body.center_of_mass(),
                                                 base.body.gyrostat()),
                            base.field};
    };
  }
  if (key == "field.g" || key == "field.lambda") {
    const bool g = key == "field.g";
    return [base, g](double p) {
      if (!std::isfinite(p))
        throw InputError("field: expected a finite value, found " + format_number(p));
      QuadraticModel m = base;
      (g ? m.field.g : m.field.lambda_) = p;
      return m;
    };
  }
  throw InputError(
      "parameter: expected body.inertia[0..2], body.center_of_mass[0..2], body.mass, field.g or "
      "field.lambda, found '" +
      key + "'");
}

Family rest_family(const QuadraticPath& path, const Vec3& gamma0, double p0, double p1,
                   const ContinuationSettings& settings) {
  path(p1);  // throws for an end outside the problem's domain, before any work
  const QuadraticModel start = path(p0);
  if (start.body.gyrostat() != Vec3::Zero()) {
    throw InputError("equilibrium family: expected a body without gyrostatic moment");
  }
  const double kappa0 = gamma0.dot(start.field.lambda_ * start.body.inertia().cwiseProduct(gamma0) +
                                   start.body.mass() * start.field.g * start.body.center_of_mass());
  Eigen::VectorXd u0(4);
  u0 << gamma0, kappa0;
  if (!(rest_residual(start, u0).cwiseAbs().maxCoeff() <= kStartTolerance)) {
    throw InputError("equilibrium family: the initial gamma is not an equilibrium at rest (" +
                     format_number(rest_residual(start, u0).norm()) + " from one)");
  }
  ContinuationProblem pr;
  pr.unknowns = 4;
  pr.residual = [&path](const Eigen::VectorXd& u, double p) { return rest_residual(path(p), u); };
  pr.jacobian = [&path](const Eigen::VectorXd& u, double p) {
    const QuadraticModel m = path(p);
    const Vec3 g = u.head<3>();
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(4, 5);
    j.topLeftCorner<3, 3>() =
        (m.field.lambda_ * m.body.inertia().array() - u[3]).matrix().asDiagonal();
    j.block<3, 1>(0, 3) = -g;
    j.block<1, 3>(3, 0) = g.transpose();
    // ∂F/∂p by a central difference: the keys enter F linearly, so only round-off remains.
    const double h = 6e-6 * std::max(1.0, std::abs(p));
    j.col(4) = (rest_residual(path(p + h), u) - rest_residual(path(p - h), u)) / (2 * h);
    return j;
  };
  pr.evaluate = [&path](const Eigen::VectorXd& u, double p) {
    const QuadraticModel m = path(p);
    const Vec3 g = u.head<3>();
    const Spectrum sp = linear_stability(Model(m), State{Vec3::Zero(), g});
    FamilyPoint pt;
    pt.values = u;
    pt.multipliers = sp.eigenvalues;
    pt.stability = to_string(make_equilibrium(m, g).type);
    return pt;
  };
  pr.branch_points = true;
  return continue_family(pr, u0, p0, p1, settings);
}

}  // namespace newtop
