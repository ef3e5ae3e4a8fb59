#include "newtop/orbit/orbit_stability.hpp"

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

}  // namespace

OrbitJacobian jacobian(const CircularOrbitModel& model, const OrbitState& s) {
  const Body& b = model.body();
  const Vec3 w = omega(b, s);
  const double w0 = model.orbit().rate, lambda = model.orbit().lambda_;
  const Mat3 I = b.inertia_matrix();
  const Mat3 I_inv = b.inertia().cwiseInverse().asDiagonal();
  OrbitJacobian J = OrbitJacobian::Zero();
  J.block<3, 3>(0, 0) = cross_matrix(s.m) * I_inv - cross_matrix(w);
  J.block<3, 3>(0, 3) = lambda * (cross_matrix(s.gamma) * I - cross_matrix(I * s.gamma));
  J.block<3, 3>(3, 0) = cross_matrix(s.gamma) * I_inv;
  J.block<3, 3>(3, 3) = -cross_matrix(w) + w0 * cross_matrix(s.normal);
  J.block<3, 3>(3, 6) = -w0 * cross_matrix(s.gamma);
  J.block<3, 3>(6, 0) = cross_matrix(s.normal) * I_inv;
  J.block<3, 3>(6, 6) = -cross_matrix(w);
  return J;
}

OrbitJacobian jacobian(const EllipticOrbitModel& model, const OrbitState& s, double nu) {
  const CircularOrbitModel body_part(model.body(),
                                     CircularOrbit::forced(0.0, lambda_at(model.orbit(), nu)));
  OrbitJacobian J = time_per_anomaly(model.orbit(), nu) * jacobian(body_part, s);
  J.block<3, 3>(3, 3) += cross_matrix(s.normal);
  J.block<3, 3>(3, 6) -= cross_matrix(s.gamma);
  return J;
}

OrbitLeafBasis leaf_basis(const OrbitState& s) {
  Eigen::Matrix<double, 9, 3> N = Eigen::Matrix<double, 9, 3>::Zero();
  N.block<3, 1>(3, 0) = s.gamma;
  N.block<3, 1>(6, 1) = s.normal;
  N.block<3, 1>(3, 2) = s.normal;
  N.block<3, 1>(6, 2) = s.gamma;
  const OrbitJacobian Q = Eigen::HouseholderQR<Eigen::Matrix<double, 9, 3>>(N).householderQ();
  return Q.rightCols<6>();
}

OrbitReduced reduced_jacobian(const CircularOrbitModel& model, const OrbitState& s) {
  const OrbitLeafBasis Q = leaf_basis(s);
  return Q.transpose() * jacobian(model, s) * Q;
}

double fixed_point_residual(const CircularOrbitModel& model, const OrbitState& s) {
  const OrbitState f = rhs(model, s);
  const Vec3 w = omega(model.body(), s);
  const double scale_m =
      s.m.norm() * w.norm() + std::abs(model.orbit().lambda_) * model.body().inertia().maxCoeff();
  const double scale_g = w.norm() + model.orbit().rate;
  const double scale_n = w.norm();
  auto term = [](double r, double scale) { return r == 0.0 ? 0.0 : r / scale; };
  return term(f.m.norm(), scale_m) + term(f.gamma.norm(), scale_g) + term(f.normal.norm(), scale_n);
}

OrbitState relative_rest_state(const CircularOrbitModel& model, const Vec3& gamma,
                               const Vec3& normal) {
  const Body& b = model.body();
  return {model.orbit().rate * b.inertia().cwiseProduct(normal) + b.gyrostat(), gamma, normal};
}

Eigen::Matrix<double, 7, 1> characteristic_polynomial(const CircularOrbitModel& model,
                                                      const OrbitState& s) {
  const Eigen::Matrix<std::complex<double>, 6, 1> z =
      Eigen::EigenSolver<OrbitReduced>(reduced_jacobian(model, s), false).eigenvalues();
  // Π (s − z_i), coefficients constant first.
  Eigen::Matrix<std::complex<double>, 7, 1> c = Eigen::Matrix<std::complex<double>, 7, 1>::Zero();
  c[0] = 1.0;
  for (int i = 0; i < 6; ++i) {
    for (int k = i + 1; k >= 1; --k) c[k] = c[k - 1] - z[i] * c[k];
    c[0] = -z[i] * c[0];
  }
  return c.real();
}

OrbitReduced energy_casimir_hessian(const CircularOrbitModel& model, const OrbitState& s) {
  const Body& b = model.body();
  const double w0 = model.orbit().rate, lambda = model.orbit().lambda_;
  const Vec3 Ig = b.inertia().cwiseProduct(s.gamma);
  const double mu1 = -lambda * s.gamma.dot(Ig);
  const double mu2 = w0 * s.m.dot(s.normal);
  const double mu3 = -lambda * s.normal.dot(Ig);
  OrbitJacobian D2 = OrbitJacobian::Zero();
  const Mat3 E = Mat3::Identity();
  D2.block<3, 3>(0, 0) = b.inertia().cwiseInverse().asDiagonal();
  D2.block<3, 3>(0, 6) = -w0 * E;
  D2.block<3, 3>(6, 0) = -w0 * E;
  D2.block<3, 3>(3, 3) = lambda * b.inertia_matrix() + mu1 * E;
  D2.block<3, 3>(6, 6) = mu2 * E;
  D2.block<3, 3>(3, 6) = mu3 * E;
  D2.block<3, 3>(6, 3) = mu3 * E;
  const OrbitLeafBasis Q = leaf_basis(s);
  return Q.transpose() * D2 * Q;
}

const char* to_string(OrbitStability v) {
  switch (v) {
    case OrbitStability::lyapunov:
      return "lyapunov";
    case OrbitStability::gyroscopic:
      return "gyroscopic";
    case OrbitStability::unstable:
      break;
  }
  return "unstable";
}

RelativeSpectrum relative_equilibrium_stability(const CircularOrbitModel& model,
                                                const OrbitState& s) {
  const OrbitReduced Jr = reduced_jacobian(model, s);
  const Eigen::Matrix<std::complex<double>, 6, 1> z =
      Eigen::EigenSolver<OrbitReduced>(Jr, false).eigenvalues();
  RelativeSpectrum out;
  out.eigenvalues.assign(z.begin(), z.end());
  std::sort(out.eigenvalues.begin(), out.eigenvalues.end(), [](const auto& a, const auto& b) {
    return a.real() != b.real() ? a.real() > b.real() : a.imag() > b.imag();
  });
  out.characteristic = characteristic_polynomial(model, s);
  out.max_real_part = out.eigenvalues.front().real();
  out.linearly_stable = out.max_real_part <= kOrbitSpectralTolerance * Jr.norm();
  const OrbitReduced h = energy_casimir_hessian(model, s);
  const Eigen::Matrix<double, 6, 1> e =
      Eigen::SelfAdjointEigenSolver<OrbitReduced>(h).eigenvalues();
  out.energy_casimir_definite = e[0] > kOrbitSpectralTolerance * e.cwiseAbs().maxCoeff();
  out.verdict = !out.linearly_stable          ? OrbitStability::unstable
                : out.energy_casimir_definite ? OrbitStability::lyapunov
                                              : OrbitStability::gyroscopic;
  return out;
}

}  // namespace newtop
