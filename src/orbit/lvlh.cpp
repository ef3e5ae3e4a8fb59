// The LVLH frame and the attitude relative to it (lvlh.hpp).

#include "newtop/orbit/lvlh.hpp"

#include <algorithm>
#include <cmath>

namespace newtop {

Mat3 lvlh_to_body(const OrbitState& s) {
  Mat3 C;
  C.col(0) = s.normal.cross(s.gamma);
  C.col(1) = -s.normal;
  C.col(2) = -s.gamma;
  return C;
}

Quaternion lvlh_quaternion(const Mat3& body_from_lvlh) {
  Quaternion q(Mat3(body_from_lvlh.transpose()));
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return q;
}

Mat3 frame_rotation(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;
  Mat3 R = Mat3::Zero();
  R(axis, axis) = 1.0;
  R(j, j) = c;
  R(k, k) = c;
  R(j, k) = s;
  R(k, j) = -s;
  return R;
}

namespace {

/// Below this |cos θ| (3-2-1) or |sin θ| (3-1-3) the outer angles are taken as one: √ε, as
/// newtop/model/attitude.hpp does (the rotation is then reproduced to about √ε).
constexpr double kGimbalLock = 1.4901161193847656e-08;

}  // namespace

Vec3 roll_pitch_yaw(const Mat3& C) {
  // C = R1(φ)R2(θ)R3(ψ): C13 = −sin θ, (C11, C12) = cos θ (cos ψ, sin ψ),
  // (C33, C23) = cos θ (cos φ, sin φ). At cos θ = 0 only ψ ∓ φ is defined: φ = 0 and
  // (C22, −C21) = (cos ψ, sin ψ).
  // θ from atan2(sin θ, cos θ), cos θ = |(C11, C12)| ≥ 0: as accurate near ±π/2 as elsewhere
  // (asin(−C13) loses half the digits there).
  const double pitch = std::atan2(-C(0, 2), std::hypot(C(0, 0), C(0, 1)));
  if (std::hypot(C(0, 0), C(0, 1)) < kGimbalLock) {
    return {0.0, pitch, std::atan2(-C(1, 0), C(1, 1))};
  }
  return {std::atan2(C(1, 2), C(2, 2)), pitch, std::atan2(C(0, 1), C(0, 0))};
}

Mat3 body_from_roll_pitch_yaw(const Vec3& a) {
  return frame_rotation(0, a[0]) * frame_rotation(1, a[1]) * frame_rotation(2, a[2]);
}

Vec3 lvlh_euler_313(const Mat3& C) {
  // C = R3(ψ)R1(θ)R3(φ): C33 = cos θ, (C31, −C32) = sin θ (sin φ, cos φ),
  // (C13, C23) = sin θ (sin ψ, cos ψ).
  // At sin θ = 0 only ψ ± φ is defined: φ = 0 and (C11, ±C12) = (cos ψ, sin ψ) (+ at θ = 0).
  const double theta = std::acos(std::clamp(C(2, 2), -1.0, 1.0));
  if (std::hypot(C(2, 0), C(2, 1)) < kGimbalLock) {
    return {0.0, theta, std::atan2(C(2, 2) > 0 ? C(0, 1) : -C(0, 1), C(0, 0))};
  }
  return {std::atan2(C(2, 0), -C(2, 1)), theta, std::atan2(C(0, 2), C(1, 2))};
}

}  // namespace newtop
