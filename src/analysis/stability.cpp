#include "newtop/analysis/stability.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
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
  return omega(model.body(), s).dot(s.gamma) / s.gamma.squaredNorm();
}

// Newton steps of polish_fixed_point; quadratic convergence from 1e-3 needs about 5.
constexpr int kPolishIterations = 50;
// Singular values of the scaled Newton matrix below this fraction of the largest are treated as
// zero: the fixed points of a family (Ω along the spin, the cone) make it singular at the
// solution, and the least-norm step leaves such directions alone. Far above eps (round-off in
// a matrix of size ~1), far below the O(1) singular values of a non-degenerate fixed point.
constexpr double kPolishRank = 1e-10;

/// Distance from the fixed points that Newton reduces: the residual plus ||γ| − 1|.
double polish_merit(const Model& model, const State& s) {
  return fixed_point_residual(model, s) + std::abs(s.gamma.norm() - 1.0);
}

/// One least-norm Newton step for F = (rhs_m / scale_m, rhs_γ / scale_g, ½(|γ|² − 1)) = 0 in the
/// unknowns (m / m_scale, γ), or in γ alone at rest (ω = 0 kept, rhs_γ = 0 there).
State newton_step(const Model& model, const State& s, bool at_rest, double m_scale, double scale_m,
                  double scale_g) {
  const State f = rhs(model, s);
  const Mat6 J = jacobian(model, s);
  Eigen::Matrix<double, 7, 6> D = Eigen::Matrix<double, 7, 6>::Zero();
  Eigen::Matrix<double, 7, 1> F = Eigen::Matrix<double, 7, 1>::Zero();
  D.topRows<3>() = J.topRows<3>() / scale_m;
  F.head<3>() = f.m / scale_m;
  if (!at_rest) {
    D.middleRows<3>(3) = J.bottomRows<3>() / scale_g;
    F.segment<3>(3) = f.gamma / scale_g;
  }
  D.leftCols<3>() *= m_scale;
  D.block<1, 3>(6, 3) = s.gamma.transpose();
  F[6] = 0.5 * (s.gamma.squaredNorm() - 1.0);
  if (at_rest) D.leftCols<3>().setZero();  // m = k stays: only γ moves
  Eigen::JacobiSVD<Eigen::Matrix<double, 7, 6>> svd(D, Eigen::ComputeFullU | Eigen::ComputeFullV);
  svd.setThreshold(kPolishRank);
  const Eigen::Matrix<double, 6, 1> dx = svd.solve(F);
  return {s.m - m_scale * dx.head<3>(), s.gamma - dx.tail<3>()};
}

}  // namespace

PolishedFixedPoint polish_fixed_point(const Model& model, const State& s) {
  PolishedFixedPoint out;
  out.state = s;
  out.residual_given = out.residual = fixed_point_residual(model, s);
  const Vec3 w = omega(model.body(), s);
  const bool at_rest = w.isZero(0.0);
  const double m_scale = at_rest ? 1.0 : s.m.norm();
  // Row scales of the residual, fixed at the given state (as in fixed_point_residual).
  const double scale_m = s.m.norm() * w.norm() + grad_gamma(model, s.gamma).norm();
  const double scale_g = at_rest ? 1.0 : w.norm();
  double merit = polish_merit(model, s);
  for (int it = 0; it < kPolishIterations && merit > 0.0 && scale_m > 0.0; ++it) {
    const State next = newton_step(model, out.state, at_rest, m_scale, scale_m, scale_g);
    const double next_merit = polish_merit(model, next);
    if (!(next_merit < merit)) break;  // converged to round-off (or diverging): keep the best
    out.state = next;
    merit = next_merit;
    out.iterations = it + 1;
  }
  out.residual = fixed_point_residual(model, out.state);
  out.correction = (out.state.gamma - s.gamma).norm();
  if (!at_rest) out.correction = std::max(out.correction, (out.state.m - s.m).norm() / m_scale);
  out.converged = out.residual <= kFixedPointTolerance && out.correction <= kPolishRadius;
  return out;
}

Mat6 jacobian(const Model& model, const State& s) {
  const Vec3 w = omega(model.body(), s);
  const Mat3 I_inv = model.body().inertia().cwiseInverse().asDiagonal();
  Mat6 J;
  J.topLeftCorner<3, 3>() = cross_matrix(s.m) * I_inv - cross_matrix(w);
  J.topRightCorner<3, 3>() = moment_jacobian(model, s.gamma);
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
  const Vec3 w = omega(model.body(), s);
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
  D2.topLeftCorner<3, 3>() = model.body().inertia().cwiseInverse().asDiagonal();
  D2.topRightCorner<3, 3>() = mu * Mat3::Identity();
  D2.bottomLeftCorner<3, 3>() = mu * Mat3::Identity();
  D2.bottomRightCorner<3, 3>() = hessian_gamma(model, s.gamma) + nu * Mat3::Identity();
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
