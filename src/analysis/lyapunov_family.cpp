// The Lyapunov families of the Euler–Poisson equations near a stable equilibrium at rest
// (docs/continuation.md §4c).

#include "newtop/analysis/lyapunov_family.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>

#include "newtop/analysis/stability.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop {

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat63 = Eigen::Matrix<double, 6, 3>;
// Bulirsch–Stoer tolerance of the shooting (absolute and relative).
constexpr double kShootingTolerance = 1e-12;
// A multiplier counts as on the unit circle within this (the shooting's accuracy, squared-rooted
// for a Jordan block at the stability boundary).
constexpr double kUnitCircle = 1e-6;

State state_of(const Vec6& x) { return {x.head<3>(), x.tail<3>()}; }
Vec6 vec_of(const State& s) { return (Vec6() << s.m, s.gamma).finished(); }

/// [∇H ∇C1 ∇C2] at x: ∇H = (ω, b + λIγ), C1 = γ·γ/2, C2 = m·γ.
Mat63 gradients(const QuadraticModel& m, const Vec6& x) {
  const Vec3 mm = x.head<3>(), g = x.tail<3>();
  Mat63 G;
  G.col(0) << mm.cwiseQuotient(m.body.inertia()),
      m.body.mass() * m.field.g * m.body.center_of_mass() +
          m.field.lambda_ * m.body.inertia().cwiseProduct(g);
  G.col(1) << Vec3::Zero(), g;
  G.col(2) << g, mm;
  return G;
}

/// The unfolded field and its Jacobian.
Vec6 field(const QuadraticModel& m, const Vec6& x, const Eigen::Vector3d& beta) {
  return vec_of(rhs(m, state_of(x))) + gradients(m, x) * beta;
}

Mat6 field_jacobian(const QuadraticModel& m, const Vec6& x, const Eigen::Vector3d& beta) {
  Mat6 a = jacobian(Model(m), state_of(x));
  a.topLeftCorner<3, 3>().diagonal() += beta[0] * m.body.inertia().cwiseInverse();
  a.bottomRightCorner<3, 3>().diagonal() +=
      Vec3::Constant(beta[1]) + beta[0] * m.field.lambda_ * m.body.inertia();
  a.topRightCorner<3, 3>().diagonal().array() += beta[2];
  a.bottomLeftCorner<3, 3>().diagonal().array() += beta[2];
  return a;
}

struct Flow {
  Vec6 x;
  Mat6 phi;
  Mat63 psi;
};

/// x(T), Φ = ∂x(T)/∂x0 and Ψ = ∂x(T)/∂β of the unfolded field.
Flow flow(const QuadraticModel& m, const Vec6& x0, double T, const Eigen::Vector3d& beta) {
  namespace ode = boost::numeric::odeint;
  using S = std::array<double, 60>;
  S y{};
  Eigen::Map<Vec6>(y.data()) = x0;
  Eigen::Map<Mat6>(y.data() + 6) = Mat6::Identity();
  auto f = [&](const S& s, S& d, double) {
    const Vec6 x = Eigen::Map<const Vec6>(s.data());
    const Mat6 a = field_jacobian(m, x, beta);
    Eigen::Map<Vec6>(d.data()) = field(m, x, beta);
    Eigen::Map<Mat6>(d.data() + 6) = a * Eigen::Map<const Mat6>(s.data() + 6);
    Eigen::Map<Mat63>(d.data() + 42) = a * Eigen::Map<const Mat63>(s.data() + 42) + gradients(m, x);
  };
  ode::integrate_adaptive(ode::bulirsch_stoer<S>(kShootingTolerance, kShootingTolerance), f, y, 0.0,
                          T, T / 50);
  return {Eigen::Map<Vec6>(y.data()), Eigen::Map<Mat6>(y.data() + 6),
          Eigen::Map<Mat63>(y.data() + 42)};
}

/// The leaf eigenvalues ±iω and their eigenvectors in ℝ⁶ at the equilibrium.
Eigen::ComplexEigenSolver<Eigen::Matrix<std::complex<double>, 6, 6>> modes(const QuadraticModel& m,
                                                                           const Vec6& xe) {
  return Eigen::ComplexEigenSolver<Eigen::Matrix<std::complex<double>, 6, 6>>(
      jacobian(Model(m), state_of(xe)).cast<std::complex<double>>());
}

}  // namespace

Eigen::Vector2d normal_frequencies(const QuadraticModel& model, const Vec3& gamma_eq) {
  const State s{Vec3::Zero(), gamma_eq};
  if (!(fixed_point_residual(Model(model), s) <= kFixedPointTolerance)) {
    throw InputError("lyapunov family: gamma is not an equilibrium at rest");
  }
  const Spectrum sp = linear_stability(Model(model), s);
  if (!sp.linearly_stable) {
    throw InputError("lyapunov family: the equilibrium is not linearly stable");
  }
  std::vector<double> w;
  for (const auto& z : sp.eigenvalues)
    if (z.imag() > 0) w.push_back(z.imag());
  if (w.size() != 2) throw InputError("lyapunov family: expected two normal frequencies");
  std::sort(w.begin(), w.end());
  return {w[0], w[1]};
}

Family lyapunov_family(const QuadraticModel& model, const Vec3& gamma_eq, int mode, double p0,
                       double p1, const ContinuationSettings& settings) {
  if (model.body.gyrostat() != Vec3::Zero() || (mode != 0 && mode != 1) || !(p0 > 0) ||
      !std::isfinite(p1)) {
    throw InputError("lyapunov family: expected no gyrostat, mode 0 or 1 and p0 > 0");
  }
  const double omega = normal_frequencies(model, gamma_eq)[mode];
  const Vec6 xe = vec_of({Vec3::Zero(), gamma_eq});
  const double h_eq = energy(model, state_of(xe));
  const auto es = modes(model, xe);
  int k = 0;
  for (int i = 1; i < 6; ++i)
    if (std::abs(es.eigenvalues()[i] - std::complex<double>(0, omega)) <
        std::abs(es.eigenvalues()[k] - std::complex<double>(0, omega)))
      k = i;
  const Vec6 a = es.eigenvectors().col(k).real().normalized();
  Vec6 s = es.eigenvectors().col(k).imag();
  s = (s - s.dot(a) * a).normalized();
  // ε from p0: H − H_eq = q ε² to second order along a.
  const double delta = 1e-4;
  const double q = (energy(model, state_of(xe + delta * a)) - h_eq) / (delta * delta);
  const double eps = std::sqrt(p0 / q);
  ContinuationProblem pr;
  pr.unknowns = 10;
  pr.residual = [=, &model](const Eigen::VectorXd& u, double p) {
    const Vec6 x0 = u.head<6>();
    const Flow fl = flow(model, x0, u[6], u.tail<3>());
    Eigen::VectorXd r(10);
    r.head<6>() = fl.x - x0;
    r[6] = s.dot(x0 - xe);
    r[7] = energy(model, state_of(x0)) - h_eq - p;
    r[8] = 0.5 * (x0.tail<3>().squaredNorm() - 1.0);
    r[9] = x0.head<3>().dot(x0.tail<3>());
    return r;
  };
  pr.jacobian = [=, &model](const Eigen::VectorXd& u, double) {
    const Vec6 x0 = u.head<6>();
    const Eigen::Vector3d beta = u.tail<3>();
    const Flow fl = flow(model, x0, u[6], beta);
    const Mat63 g = gradients(model, x0);
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(10, 11);
    j.topLeftCorner<6, 6>() = fl.phi - Mat6::Identity();
    j.block<6, 1>(0, 6) = field(model, fl.x, beta);
    j.block<6, 3>(0, 7) = fl.psi;
    j.block<1, 6>(6, 0) = s.transpose();
    j.block<1, 6>(7, 0) = g.col(0).transpose();
    j(7, 10) = -1.0;
    j.block<1, 6>(8, 0) = g.col(1).transpose();
    j.block<1, 6>(9, 0) = g.col(2).transpose();
    return j;
  };
  pr.evaluate = [&model](const Eigen::VectorXd& u, double) {
    const Flow fl = flow(model, u.head<6>(), u[6], u.tail<3>());
    const Eigen::EigenSolver<Mat6> ev(fl.phi);
    FamilyPoint pt;
    pt.values = u.head<6>();
    pt.period = u[6];
    double farthest = 0.0;
    for (int i = 0; i < 6; ++i) {
      pt.multipliers.push_back(ev.eigenvalues()[i]);
      farthest = std::max(farthest, std::abs(std::abs(ev.eigenvalues()[i]) - 1.0));
    }
    pt.stability = farthest <= kUnitCircle ? "stable" : "unstable";
    pt.tests = {fl.phi.trace() - 2, fl.phi.trace() - 6};
    return pt;
  };
  pr.tests = {{BifurcationType::flip, {}}, {BifurcationType::branch_point, {}}};
  Eigen::VectorXd u0 = Eigen::VectorXd::Zero(10);
  u0.head<6>() = xe + eps * a;
  u0[6] = 2 * std::numbers::pi / omega;
  return continue_family(pr, u0, p0, p1, settings);
}

}  // namespace newtop
