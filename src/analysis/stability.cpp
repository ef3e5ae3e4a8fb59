#include "newtop/analysis/stability.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace newtop {
namespace {

Mat3 cross_matrix(const Vec3& a) {
  Mat3 m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

/// Ω with ω = Ω γ at a fixed point (0 at rest).
double spin_rate(const Model& model, const State& s) {
  return omega(model.body, s).dot(s.gamma) / s.gamma.squaredNorm();
}

}  // namespace

Mat6 jacobian(const Model& model, const State& s) {
  const Vec3 w = omega(model.body, s);
  const Mat3 I_inv = model.body.inertia().cwiseInverse().asDiagonal();
  const Mat3 H = hessian_gamma(model.body, model.field, s.gamma);
  Mat6 J;
  J.topLeftCorner<3, 3>() = cross_matrix(s.m) * I_inv - cross_matrix(w);
  J.topRightCorner<3, 3>() = cross_matrix(s.gamma) * H - cross_matrix(grad_gamma(model, s.gamma));
  J.bottomLeftCorner<3, 3>() = cross_matrix(s.gamma) * I_inv;
  J.bottomRightCorner<3, 3>() = -cross_matrix(w);
  return J;
}

LeafBasis leaf_basis(const State& s) {
  Eigen::Matrix<double, 6, 2> N;
  N << Vec3::Zero(), s.gamma, s.gamma, s.m;  // columns: ∇C1, ∇C2
  const Mat6 Q = Eigen::HouseholderQR<Eigen::Matrix<double, 6, 2>>(N).householderQ();
  return Q.rightCols<4>();
}

Eigen::Matrix4d reduced_jacobian(const Model& model, const State& s) {
  const LeafBasis Q = leaf_basis(s);
  return Q.transpose() * jacobian(model, s) * Q;
}

double fixed_point_residual(const Model& model, const State& s) {
  const State f = rhs(model, s);
  const Vec3 w = omega(model.body, s);
  const double scale_m = s.m.norm() * w.norm() + grad_gamma(model, s.gamma).norm();
  const double scale_g = w.norm();
  const double rm = f.m.norm(), rg = f.gamma.norm();
  return (rm == 0.0 ? 0.0 : rm / scale_m) + (rg == 0.0 ? 0.0 : rg / scale_g);
}

Eigen::Matrix4d energy_casimir_hessian(const Model& model, const State& s) {
  // F = H + μ C2 + ν C1, C1 = ½ γ·γ, C2 = m·γ. dF = 0: ω + μ γ = 0 → μ = −Ω;
  // ∂V/∂γ + μ m + ν γ = 0 → ν = −γ·(∂V/∂γ + μ m) (the rest vanishes at a fixed point).
  const double mu = -spin_rate(model, s);
  const double nu = -s.gamma.dot(grad_gamma(model, s.gamma) + mu * s.m) / s.gamma.squaredNorm();
  Mat6 D2;
  D2.topLeftCorner<3, 3>() = model.body.inertia().cwiseInverse().asDiagonal();
  D2.topRightCorner<3, 3>() = mu * Mat3::Identity();
  D2.bottomLeftCorner<3, 3>() = mu * Mat3::Identity();
  D2.bottomRightCorner<3, 3>() =
      hessian_gamma(model.body, model.field, s.gamma) + nu * Mat3::Identity();
  const LeafBasis Q = leaf_basis(s);
  return Q.transpose() * D2 * Q;
}

bool energy_casimir_stable(const Model& model, const State& s) {
  const Eigen::Matrix4d h = energy_casimir_hessian(model, s);
  const Eigen::Vector4d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(h).eigenvalues();
  return e[0] > kSpectralTolerance * e.cwiseAbs().maxCoeff();
}

Spectrum linear_stability(const Model& model, const State& s) {
  const Eigen::Matrix4d Jr = reduced_jacobian(model, s);
  const Eigen::Vector4cd z = Eigen::EigenSolver<Eigen::Matrix4d>(Jr, false).eigenvalues();
  Spectrum out;
  out.eigenvalues.assign(z.begin(), z.end());
  std::sort(out.eigenvalues.begin(), out.eigenvalues.end(), [](const auto& a, const auto& b) {
    return a.real() != b.real() ? a.real() > b.real() : a.imag() > b.imag();
  });
  out.max_real_part = out.eigenvalues.front().real();
  out.linearly_stable = out.max_real_part <= kSpectralTolerance * Jr.norm();
  if (!out.linearly_stable) {
    out.lyapunov_stable = false;
  } else if (energy_casimir_stable(model, s)) {
    out.lyapunov_stable = true;
  }
  return out;
}

}  // namespace newtop
