// Equilibria at rest in any field (docs/model.md §7): the critical points of V on the unit sphere,
// found by Levenberg–Marquardt on the moment L(γ) = γ × ∂V/∂γ = 0 from many starts.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/model/model.hpp"

namespace newtop {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Iterations of one Levenberg–Marquardt descent: quadratic convergence needs ~6 near a root; the
// damped steps from a start far from one (up to a quarter turn, steps ~ 0.1 rad) need ~30.
constexpr int kMaxIterations = 100;
// |L| at an accepted critical point, relative to the moment's scale over the sphere (the largest
// |L| at the starts): the cancellation-free moments are accurate to a few ulps of that scale.
constexpr double kMomentTolerance = 1e-11;
// Two critical points closer than this (radians) are one: converged points agree to ~1e-13, and
// distinct critical points of a body's field are 1e-3 rad apart or more unless degenerate.
constexpr double kSamePoint = 1e-7;
// A sphere-Hessian eigenvalue below this fraction of the Hessian scale counts as zero (the
// Hessians are accurate to ~1e-12 of their scale; a genuine zero is a family of equilibria).
constexpr double kHessianTolerance = 1e-8;

/// Orthonormal t1, t2 with t1 × t2 = γ.
Eigen::Matrix<double, 3, 2> tangent_basis(const Vec3& g) {
  const Vec3 a = std::abs(g.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t1 = g.cross(a).normalized();
  Eigen::Matrix<double, 3, 2> T;
  T.col(0) = t1;
  T.col(1) = g.cross(t1);
  return T;
}

/// The 2×2 Jacobian of ℓ = Tᵀ L along the sphere: Tᵀ (∂L/∂γ) T.
Eigen::Matrix2d reduced_moment_jacobian(const Model& model, const Vec3& g,
                                        const Eigen::Matrix<double, 3, 2>& T) {
  return T.transpose() * moment_jacobian(model, g) * T;
}

/// One descent from γ0; the point and its |L|.
std::pair<Vec3, double> descend(const Model& model, const Vec3& g0) {
  Vec3 g = g0.normalized();
  double r = moment(model, g).norm();
  double damping = 1e-3;
  for (int it = 0; it < kMaxIterations && r > 0.0; ++it) {
    const Eigen::Matrix<double, 3, 2> T = tangent_basis(g);
    const Eigen::Vector2d l = T.transpose() * moment(model, g);
    const Eigen::Matrix2d J = reduced_moment_jacobian(model, g, T);
    const Eigen::Matrix2d JtJ = J.transpose() * J;
    bool improved = false;
    for (int k = 0; k < 30 && !improved; ++k) {
      Eigen::Matrix2d A = JtJ;
      A.diagonal() += damping * JtJ.diagonal().cwiseMax(kEps * JtJ.norm());
      Eigen::Vector2d step = -A.ldlt().solve(J.transpose() * l);
      if (step.norm() > 0.5) step *= 0.5 / step.norm();  // at most ~30° at a time
      const Vec3 next = (g + T * step).normalized();
      const double rn = moment(model, next).norm();
      if (rn < r) {
        const double dg = (next - g).norm();
        g = next;
        r = rn;
        damping = std::max(damping / 10, 1e-12);
        improved = true;
        if (dg <= 4 * kEps) return {g, r};
      } else {
        damping *= 10;
      }
    }
    if (!improved) break;
  }
  return {g, r};
}

}  // namespace

std::vector<Vec3> fibonacci_sphere(int n) {
  std::vector<Vec3> p;
  p.reserve(n);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    p.emplace_back(rho * std::cos(golden * i), rho * std::sin(golden * i), z);
  }
  return p;
}

Eigen::Matrix2d sphere_hessian(const Model& model, const Vec3& gamma) {
  // At a critical point Tᵀ (∂L/∂γ) T = R Tᵀ (∂²V/∂γ² − κ E) T with R the quarter turn
  // [[0, −1], [1, 0]] of the tangent plane (∂L/∂γ = [γ]× (∂²V/∂γ² − κE) − [∂V/∂γ − κγ]×, the last
  // term zero there), so the sphere's Hessian is Rᵀ Tᵀ (∂L/∂γ) T, free of the cancellation in
  // ∂²V/∂γ² − κE far from the body.
  const Eigen::Matrix<double, 3, 2> T = tangent_basis(gamma);
  Eigen::Matrix2d Rt;
  Rt << 0, 1, -1, 0;
  const Eigen::Matrix2d h = Rt * reduced_moment_jacobian(model, gamma, T);
  return 0.5 * (h + h.transpose());
}

EquilibriumSet sphere_equilibria(const Model& model, const std::vector<Vec3>& starts) {
  double moment_scale = 0.0;
  for (const Vec3& s : starts)
    moment_scale = std::max(moment_scale, moment(model, s.normalized()).norm());
  EquilibriumSet set;
  if (moment_scale == 0.0) {
    set.every_orientation = true;
    return set;
  }
  std::vector<Vec3> found;
  for (const Vec3& s : starts) {
    const std::pair<Vec3, double> d = descend(model, s);
    const Vec3& g = d.first;  // no structured binding: a lambda captures it
    if (!(d.second <= kMomentTolerance * moment_scale)) continue;
    const bool seen = std::any_of(found.begin(), found.end(),
                                  [&](const Vec3& f) { return (f - g).norm() <= kSamePoint; });
    if (!seen) found.push_back(g);
  }
  std::vector<Eigen::Matrix2d> hessians;
  double hessian_scale = 0.0;
  for (const Vec3& g : found) {
    hessians.push_back(sphere_hessian(model, g));
    hessian_scale = std::max(hessian_scale, hessians.back().norm());
  }
  for (std::size_t i = 0; i < found.size(); ++i) {
    Equilibrium e;
    e.gamma = found[i];
    e.kappa = found[i].dot(grad_gamma(model, found[i]));
    e.potential = potential(model, found[i]);
    e.hessian = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(hessians[i]).eigenvalues();
    e.staude_residual = std::numeric_limits<double>::quiet_NaN();  // no cone outside §3's field
    const double tol = kHessianTolerance * hessian_scale;
    if (std::abs(e.hessian[0]) <= tol || std::abs(e.hessian[1]) <= tol) {
      e.type = EquilibriumType::degenerate;
      ++set.degenerate;
    } else if (e.hessian[0] > 0) {
      e.type = EquilibriumType::minimum;
      ++set.minima;
    } else if (e.hessian[1] < 0) {
      e.type = EquilibriumType::maximum;
      ++set.maxima;
    } else {
      e.type = EquilibriumType::saddle;
      ++set.saddles;
    }
    set.equilibria.push_back(e);
  }
  std::sort(set.equilibria.begin(), set.equilibria.end(),
            [](const Equilibrium& a, const Equilibrium& b) { return a.kappa < b.kappa; });
  return set;
}

EquilibriumSet find_equilibria(const Model& model) {
  if (model.kind() == FieldKind::quadratic) return find_equilibria(model.quadratic());
  // Starts: the quadratic model's equilibria (continued into the field: the nearest critical
  // points when the body is small against R) and points on circles of equilibria, then a
  // Fibonacci lattice of kSphereStarts points for the critical points the quadratic model lacks.
  const EquilibriumSet q = find_equilibria(quadratic_approximation(model));
  std::vector<Vec3> starts;
  for (const Equilibrium& e : q.equilibria) starts.push_back(e.gamma);
  for (const EquilibriumCircle& c : q.circles) {
    const int j = (c.axis + 1) % 3, k = (c.axis + 2) % 3;
    const double rho = std::sqrt(std::max(0.0, 1.0 - c.gamma_axis * c.gamma_axis));
    for (int i = 0; i < 8; ++i) {
      Vec3 g = Vec3::Zero();
      g[c.axis] = c.gamma_axis;
      g[j] = rho * std::cos(M_PI * i / 4);
      g[k] = rho * std::sin(M_PI * i / 4);
      starts.push_back(g);
    }
  }
  const std::vector<Vec3> lattice = fibonacci_sphere(kSphereStarts);
  starts.insert(starts.end(), lattice.begin(), lattice.end());
  return sphere_equilibria(model, starts);
}

}  // namespace newtop
