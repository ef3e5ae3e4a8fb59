#include "newtop/model/attitude.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace newtop {
namespace {

// Within this of the singular θ (|cos θ| for 3-2-1, |sin θ| for 3-1-3) the outer angles are taken
// as at the singularity: their regular formulas lose ε/|cos θ| there, the singular ones |cos θ|,
// so either way the rotation is reproduced to about √ε.
const double kGimbalLock = std::sqrt(std::numeric_limits<double>::epsilon());

}  // namespace

Quaternion from_euler_321(const Vec3& a) {
  return Quaternion(Eigen::AngleAxisd(a[0], Vec3::UnitZ()) *
                    Eigen::AngleAxisd(a[1], Vec3::UnitY()) *
                    Eigen::AngleAxisd(a[2], Vec3::UnitX()));
}

Vec3 euler_321(const Quaternion& q) {
  const Mat3 R = q.normalized().toRotationMatrix();
  // R = R_z(ψ) R_y(θ) R_x(φ): R20 = −sin θ, (R00, R10) = cos θ (cos ψ, sin ψ), (R22, R21) = cos θ
  // (cos φ, sin φ).
  const double c = std::hypot(R(0, 0), R(1, 0));
  const double theta = std::atan2(-R(2, 0), c);
  if (c > kGimbalLock) {
    return {std::atan2(R(1, 0), R(0, 0)), theta, std::atan2(R(2, 1), R(2, 2))};
  }
  // cos θ = 0: R = R_z(ψ ∓ φ) R_y(±π/2); with φ = 0, (R11, −R01) = (cos ψ, sin ψ).
  return {std::atan2(-R(0, 1), R(1, 1)), theta, 0.0};
}

Quaternion from_euler_313(const Vec3& a) {
  return Quaternion(Eigen::AngleAxisd(a[0], Vec3::UnitZ()) *
                    Eigen::AngleAxisd(a[1], Vec3::UnitX()) *
                    Eigen::AngleAxisd(a[2], Vec3::UnitZ()));
}

Vec3 euler_313(const Quaternion& q) {
  const Mat3 R = q.normalized().toRotationMatrix();
  // R = R_z(φ) R_x(θ) R_z(ψ): R22 = cos θ, (R21, R20) = sin θ (cos ψ, sin ψ), (−R12, R02) = sin θ
  // (cos φ, sin φ).
  const double s = std::hypot(R(2, 0), R(2, 1));
  const double theta = std::atan2(s, R(2, 2));
  if (s > kGimbalLock) {
    return {std::atan2(R(0, 2), -R(1, 2)), theta, std::atan2(R(2, 0), R(2, 1))};
  }
  // sin θ = 0: R = R_z(φ ± ψ) diag(1, ±1, ±1); with ψ = 0, (R00, R10) = (cos φ, sin φ).
  return {std::atan2(R(1, 0), R(0, 0)), theta, 0.0};
}

double orthonormality_defect(const Mat3& R) {
  return (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff();
}

double rotation_distance(const Quaternion& p, const Quaternion& q) {
  return p.normalized().angularDistance(q.normalized());
}

}  // namespace newtop
