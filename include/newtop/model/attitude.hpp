#pragma once
/// \file
/// The attitude of the body (docs/model.md §4 loses it: (m, γ) does not see a rotation about the
/// fixed direction e). R ∈ SO(3) maps body coordinates to inertial ones, x_inertial = R x_body, and
/// is held as the unit quaternion q of Eigen (q x q* = R x; coefficients written scalar first, (w,
/// x, y, z), everywhere newtop reads or writes them). The direction e from the centre towards the
/// body is fixed in space and γ = Rᵀ e, so a state with an attitude fixes e = R γ. The rows of R
/// are the inertial axes seen from the body, Rᵀ e_a: they move exactly as γ does (γ̇ = γ × ω), and R
/// obeys Ṙ = R [ω]×, q̇ = ½ q ⊗ (0, ω).
///
/// Euler angles (radians; docs/scenario.md):
/// - 3-2-1 (ψ, θ, φ): R = R_z(ψ) R_y(θ) R_x(φ) (yaw, pitch, roll about the body's axes as they
///   move); returned with ψ, φ in (−π, π], θ in [−π/2, π/2].
/// - 3-1-3 (φ, θ, ψ): R = R_z(φ) R_x(θ) R_z(ψ) (precession, nutation, spin); returned with φ, ψ
///   in (−π, π], θ in [0, π].
/// R_a(α) is the rotation by α about axis a (counter-clockwise seen from the axis' tip). At the
/// singular θ (cos θ = 0 for 3-2-1, sin θ = 0 for 3-1-3) only a sum or difference of the outer
/// angles is defined: the extraction returns φ = 0 (3-2-1) or ψ = 0 (3-1-3), and does so within
/// √ε of it (the rotation is then reproduced to about √ε = 1.5e-8 rad; elsewhere to round-off).

#include <Eigen/Geometry>
#include <array>
#include <concepts>

#include "newtop/model/basic_model.hpp"

namespace newtop {

using Quaternion = Eigen::Quaterniond;

/// The Euler–Poisson state (m, γ) with the attitude q (body → inertial, unit).
struct OrientedState : State {
  Quaternion q = Quaternion::Identity();

  bool operator==(const OrientedState& o) const {
    return State::operator==(o) && q.coeffs() == o.q.coeffs();
  }
};

/// A state with or without an attitude: what the steppers and the driver advance.
template <class X>
concept PhaseState = std::same_as<X, State> || std::same_as<X, OrientedState>;

template <class X>
inline constexpr bool kOriented = std::same_as<X, OrientedState>;

/// The state (m, γ) and the attitude q together.
inline OrientedState with_attitude(const State& x, const Quaternion& q) {
  OrientedState o;
  o.m = x.m;
  o.gamma = x.gamma;
  o.q = q;
  return o;
}

/// The fixed inertial direction e = R γ of a state with an attitude.
inline Vec3 inertial_direction(const OrientedState& x) { return x.q * x.gamma; }

/// q̇ = ½ q ⊗ (0, ω) (Ṙ = R [ω]×) for the body-frame angular velocity ω.
inline Quaternion attitude_rate(const Quaternion& q, const Vec3& omega) {
  Quaternion d = q * Quaternion(0.0, omega.x(), omega.y(), omega.z());
  d.coeffs() *= 0.5;
  return d;
}

/// The quaternion as (w, x, y, z).
inline std::array<double, 4> scalar_first(const Quaternion& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}

/// R of the 3-2-1 angles (ψ, θ, φ) and back (conventions above).
Quaternion from_euler_321(const Vec3& psi_theta_phi);
Vec3 euler_321(const Quaternion& q);
/// R of the 3-1-3 angles (φ, θ, ψ) and back (conventions above).
Quaternion from_euler_313(const Vec3& phi_theta_psi);
Vec3 euler_313(const Quaternion& q);

/// max |(RᵀR − I)_ij|: how far a matrix is from orthonormal.
double orthonormality_defect(const Mat3& R);

/// The angle of the rotation taking p to q (0 ≤ angle ≤ π; q and −q are the same rotation).
double rotation_distance(const Quaternion& p, const Quaternion& q);

}  // namespace newtop
