#include "newtop/analysis/equilibria.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace newtop {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Companion-matrix roots of a well-scaled polynomial are accurate to ~eps for simple roots and to
// ~sqrt(eps) ≈ 1.5e-8 for double ones (tangencies of the secular equation), so real roots can
// acquire imaginary parts of that size; candidates up to 1e-6 are kept and Newton decides.
constexpr double kImagTolerance = 1e-6;
// |f(κ)| of the dimensionless secular function at an accepted root: Newton reaches ~eps · (terms
// of size up to 1/tolerance near a pole), 1e-9 leaves room and rejects complex pairs, for which
// f stays bounded away from zero.
constexpr double kSecularResidual = 1e-9;
// A Hessian eigenvalue below this fraction of the field's scale counts as zero: κ from a double
// root is accurate to ~sqrt(eps) relative, and the Hessian eigenvalue is of the order of that
// error.
constexpr double kHessianTolerance = 1e-7;
// Two equilibria closer than this on the sphere are one (double roots seen twice).
constexpr double kSamePoint = 1e-7;

/// The data of the secular problem: b = M g r0, d = λ I, and the groups of equal d.
struct Secular {
  Vec3 b, d;
  double scale;                            // |b| + max |d_i|: the size of ∂V/∂γ
  std::vector<double> d_g;                 // distinct values of d (active groups: some b_i ≠ 0)
  std::vector<double> beta;                // Σ b_i² over the group
  std::vector<std::vector<int>> inactive;  // groups of equal d with all b_i = 0
  std::vector<double> d_inactive;
};

Secular make_secular(const QuadraticModel& model) {
  Secular s;
  s.b = model.body.mass() * model.field.g * model.body.center_of_mass();
  s.d = model.field.lambda_ * model.body.inertia();
  s.scale = s.b.norm() + s.d.cwiseAbs().maxCoeff();
  const double tol = kEquilibriumDegeneracy * s.scale;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(s.b[i]) <= tol) s.b[i] = 0.0;
  }
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return s.d[i] < s.d[j]; });
  std::vector<std::vector<int>> groups;
  for (int i : order) {
    if (!groups.empty() && std::abs(s.d[i] - s.d[groups.back().front()]) <= tol) {
      groups.back().push_back(i);
    } else {
      groups.push_back({i});
    }
  }
  for (const auto& g : groups) {
    double beta = 0.0;
    for (int i : g) beta += s.b[i] * s.b[i];
    if (beta > 0.0) {
      s.d_g.push_back(s.d[g.front()]);
      s.beta.push_back(beta);
    } else {
      s.inactive.push_back(g);
      s.d_inactive.push_back(s.d[g.front()]);
    }
  }
  return s;
}

/// Polynomial product (coefficients constant term first).
Eigen::VectorXd multiply(const Eigen::VectorXd& p, const Eigen::VectorXd& q) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(p.size() + q.size() - 1);
  for (Eigen::Index i = 0; i < p.size(); ++i) r.segment(i, q.size()) += p[i] * q;
  return r;
}

/// Secular polynomial for groups (d_g, β_g), see secular_polynomial().
Eigen::VectorXd polynomial(const std::vector<double>& d_g, const std::vector<double>& beta) {
  const auto n = static_cast<Eigen::Index>(d_g.size());
  auto squared_factor = [&](std::size_t h) {
    Eigen::VectorXd f(3);
    f << d_g[h] * d_g[h], -2.0 * d_g[h], 1.0;
    return f;
  };
  Eigen::VectorXd p = Eigen::VectorXd::Zero(2 * n + 1);
  Eigen::VectorXd all = Eigen::VectorXd::Ones(1);
  for (std::size_t h = 0; h < d_g.size(); ++h) all = multiply(all, squared_factor(h));
  for (std::size_t g = 0; g < d_g.size(); ++g) {
    Eigen::VectorXd term = Eigen::VectorXd::Constant(1, beta[g]);
    for (std::size_t h = 0; h < d_g.size(); ++h) {
      if (h != g) term = multiply(term, squared_factor(h));
    }
    p.head(term.size()) += term;
  }
  return p - all;
}

/// f(κ) = Σ β_g/(κ − d_g)² − 1 and f′(κ).
std::pair<double, double> secular_function(const Secular& s, double kappa) {
  double f = -1.0, df = 0.0;
  for (std::size_t g = 0; g < s.d_g.size(); ++g) {
    const double x = kappa - s.d_g[g];
    f += s.beta[g] / (x * x);
    df -= 2.0 * s.beta[g] / (x * x * x);
  }
  return {f, df};
}

/// Newton's method on the secular function; false if it does not settle on a root.
bool polish(const Secular& s, double& kappa) {
  for (int it = 0; it < 100; ++it) {
    const auto [f, df] = secular_function(s, kappa);
    if (!std::isfinite(f) || df == 0.0) return false;
    const double dk = f / df;
    kappa -= dk;
    if (std::abs(dk) <= 4 * kEps * std::max(std::abs(kappa), s.scale)) break;
  }
  const double f = secular_function(s, kappa).first;
  return std::isfinite(f) && std::abs(f) <= kSecularResidual;
}

Vec3 gamma_at(const Secular& s, double kappa) {
  Vec3 gamma = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    if (s.b[i] != 0.0) gamma[i] = s.b[i] / (kappa - s.d[i]);
  }
  return gamma.normalized();
}

void add_point(const QuadraticModel& model, const Vec3& gamma, EquilibriumSet& set) {
  for (const auto& e : set.equilibria) {
    if ((e.gamma - gamma).norm() <= kSamePoint) return;
  }
  set.equilibria.push_back(make_equilibrium(model, gamma));
}

/// κ = d_G for a group G whose components of b vanish (docs/model.md §7, "when a component x0_i =
/// 0").
void add_degenerate(const QuadraticModel& model, const Secular& s, std::size_t k,
                    EquilibriumSet& set) {
  const double kappa = s.d_inactive[k];
  const auto& G = s.inactive[k];
  Vec3 fixed = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    if (s.b[i] != 0.0) fixed[i] = s.b[i] / (kappa - s.d[i]);
  }
  const double rest = 1.0 - fixed.squaredNorm();
  if (rest < -kSecularResidual) return;
  const double free = std::sqrt(std::max(rest, 0.0));
  if (G.size() == 1 || free == 0.0) {
    for (double sign : {1.0, -1.0}) {
      Vec3 gamma = fixed;
      gamma[G.front()] = sign * free;
      add_point(model, gamma.normalized(), set);
    }
    return;
  }
  // Two equal λ I_i with b_i = 0: a circle in their plane (G.size() == 3 is V = const).
  const int axis = 3 - G[0] - G[1];
  set.circles.push_back(
      {axis, fixed[axis], kappa, potential(model, Vec3(fixed + free * Vec3::Unit(G[0])))});
}

}  // namespace

const char* to_string(EquilibriumType t) {
  switch (t) {
    case EquilibriumType::minimum:
      return "minimum";
    case EquilibriumType::saddle:
      return "saddle";
    case EquilibriumType::maximum:
      return "maximum";
    case EquilibriumType::degenerate:
      break;
  }
  return "degenerate";
}

Eigen::VectorXd secular_polynomial(const QuadraticModel& model) {
  const Secular s = make_secular(model);
  return polynomial(s.d_g, s.beta);
}

std::vector<double> real_polynomial_roots(const Eigen::VectorXd& c, double imag_tolerance) {
  const Eigen::Index n = c.size() - 1;
  if (n < 1) return {};
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  companion.diagonal(-1).setOnes();
  companion.col(n - 1) = -c.head(n) / c[n];
  const Eigen::VectorXcd z = Eigen::EigenSolver<Eigen::MatrixXd>(companion, false).eigenvalues();
  const double size = std::max(z.cwiseAbs().maxCoeff(), 1.0);
  std::vector<double> roots;
  for (const auto& r : z) {
    if (std::abs(r.imag()) <= imag_tolerance * size) roots.push_back(r.real());
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

Eigen::Matrix2d sphere_hessian(const QuadraticModel& model, const Vec3& gamma, double kappa) {
  // Orthonormal basis (t1, t2) of the tangent plane γ⊥.
  const Vec3 helper = std::abs(gamma.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t1 = gamma.cross(helper).normalized();
  const Vec3 t2 = gamma.cross(t1);
  Eigen::Matrix<double, 3, 2> T;
  T << t1, t2;
  const Mat3 L = hessian_gamma(model.body, model.field, gamma) - kappa * Mat3::Identity();
  return T.transpose() * L * T;
}

Equilibrium make_equilibrium(const QuadraticModel& model, const Vec3& gamma) {
  const Vec3 grad = grad_gamma(model, gamma);
  const double kappa = gamma.dot(grad);
  const Eigen::Vector2d h =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(sphere_hessian(model, gamma, kappa))
          .eigenvalues();
  const double scale =
      model.body.mass() * std::abs(model.field.g) * model.body.center_of_mass().norm() +
      std::abs(model.field.lambda_) * model.body.inertia().maxCoeff();
  const double tol = kHessianTolerance * scale;
  EquilibriumType type = EquilibriumType::saddle;
  if (std::abs(h[0]) <= tol || std::abs(h[1]) <= tol) {
    type = EquilibriumType::degenerate;
  } else if (h[0] > 0) {
    type = EquilibriumType::minimum;
  } else if (h[1] < 0) {
    type = EquilibriumType::maximum;
  }
  const Vec3& I = model.body.inertia();
  const double staude = gamma.dot(I.cwiseProduct(gamma).cross(model.body.center_of_mass()));
  return {gamma, kappa, potential(model, gamma), type, h, staude};
}

EquilibriumSet find_equilibria(const QuadraticModel& model) {
  const Secular s = make_secular(model);
  EquilibriumSet set;
  if (s.scale == 0.0 || (s.d_g.empty() && s.inactive.size() == 1)) {
    set.every_orientation = true;  // V constant on the sphere
    return set;
  }
  if (!s.d_g.empty()) {
    std::vector<double> dn(s.d_g.size()), bn(s.beta.size());
    for (std::size_t g = 0; g < dn.size(); ++g) {
      dn[g] = s.d_g[g] / s.scale;  // well-scaled polynomial in κ/scale
      bn[g] = s.beta[g] / (s.scale * s.scale);
    }
    for (double u : real_polynomial_roots(polynomial(dn, bn), kImagTolerance)) {
      double kappa = u * s.scale;
      if (polish(s, kappa)) add_point(model, gamma_at(s, kappa), set);
    }
  }
  for (std::size_t k = 0; k < s.inactive.size(); ++k) add_degenerate(model, s, k, set);
  std::sort(set.equilibria.begin(), set.equilibria.end(),
            [](const Equilibrium& a, const Equilibrium& b) { return a.kappa < b.kappa; });
  for (const auto& e : set.equilibria) {
    set.minima += e.type == EquilibriumType::minimum;
    set.saddles += e.type == EquilibriumType::saddle;
    set.maxima += e.type == EquilibriumType::maximum;
    set.degenerate += e.type == EquilibriumType::degenerate;
  }
  return set;
}

}  // namespace newtop
