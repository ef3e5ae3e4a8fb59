#include "newtop/model/body.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace newtop {
namespace {

// The triangle inequality A + B >= C is tested with a slack of a few ulps of the trace, so that a
// limiting body (a rod or a plate, where equality holds exactly) survives the round-off of a
// diagonalisation.
constexpr double kTriangleSlack = 8 * 2.220446049250313e-16;

void check_finite(const char* name, const Vec3& v) {
  if (!v.allFinite()) {
    throw InputError(std::string(name) + ": expected finite numbers, found " + format_vector(v));
  }
}

// `field` names the input the moments came from: inertia (given) or inertia_tensor (its
// eigenvalues).
void check_moments(const Vec3& I, const std::string& field) {
  check_finite(field.c_str(), I);
  const char* names[3] = {"A", "B", "C"};
  for (int i = 0; i < 3; ++i) {
    if (!(I[i] > 0)) {
      throw InputError(field + ": expected positive principal moments, found " + names[i] + " = " +
                       format_number(I[i]));
    }
  }
  // Compared relative to the largest moment, so that no sum overflows (A + B of moments near
  // 1e308 would pass any test as inf).
  const Vec3 u = I / I.maxCoeff();
  const double slack = kTriangleSlack * u.sum();
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (u[i] + u[j] < u[k] - slack) {
      throw InputError(field + ": triangle inequality " + names[i] + " + " + names[j] +
                       " >= " + names[k] + " fails: " + format_number(I[i]) + " + " +
                       format_number(I[j]) + " < " + format_number(I[k]));
    }
  }
}

void check_mass(double mass) {
  if (!std::isfinite(mass) || mass < 0) {
    throw InputError("mass: expected a finite number >= 0, found " + format_number(mass));
  }
}

}  // namespace

Body Body::from_principal(const Vec3& inertia, double mass, const Vec3& center_of_mass,
                          const Vec3& gyrostat) {
  check_moments(inertia, "inertia");
  check_mass(mass);
  check_finite("center_of_mass", center_of_mass);
  check_finite("gyrostat", gyrostat);
  return Body(inertia, mass, center_of_mass, gyrostat, Mat3::Identity());
}

Body Body::from_tensor(const Mat3& J, double mass, const Vec3& center_of_mass,
                       const Vec3& gyrostat) {
  if (!J.allFinite())
    throw InputError("inertia_tensor: expected finite numbers, found a NaN or inf");
  const double scale = J.cwiseAbs().maxCoeff();
  const double asym = (J - J.transpose()).cwiseAbs().maxCoeff();
  if (asym > 1e-12 * scale) {
    throw InputError("inertia_tensor: expected a symmetric matrix, found max |J_ij - J_ji| = " +
                     format_number(asym));
  }
  Mat3 off = J;
  off.diagonal().setZero();
  if (off.cwiseAbs().maxCoeff() == 0.0) {
    return from_principal(J.diagonal(), mass, center_of_mass, gyrostat);
  }
  Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (J + J.transpose()));
  Mat3 P = eig.eigenvectors();
  if (P.determinant() < 0) P.col(2) = -P.col(2);
  check_moments(eig.eigenvalues(), "inertia_tensor");
  check_mass(mass);
  check_finite("center_of_mass", center_of_mass);
  check_finite("gyrostat", gyrostat);
  return Body(eig.eigenvalues(), mass, P.transpose() * center_of_mass, P.transpose() * gyrostat, P);
}

}  // namespace newtop
