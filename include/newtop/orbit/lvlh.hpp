#pragma once
/// \file
/// The attitude of a satellite relative to its orbital frame in the convention of attitude
/// engineering (docs/orbit.md §11): the LVLH frame (local vertical, local horizontal)
///
///   z_L = −γ (to nadir, towards the centre),  y_L = −n (opposite the orbit normal),
///   x_L = y_L × z_L = n × γ (along-track: the velocity's direction on a circular orbit),
///
/// and the direction cosine matrix C = C(body←LVLH), v_body = C v_LVLH, whose columns are the LVLH
/// axes in body components. Its Euler parameters q = (q0, q1, q2, q3) (scalar first, q0 ≥ 0;
/// the rotation carrying the LVLH axes onto the body axes, Schaub & Junkins' β_BR):
/// C = (q0² − q·q) I + 2 q qᵀ − 2 q0 [q×], q = (q1, q2, q3). Its 3-2-1 angles (roll φ, pitch θ,
/// yaw ψ): C = R1(φ) R2(θ) R3(ψ), R_i(a) the frame rotation about axis i
/// (R3(a) = [[c, s, 0], [−s, c, 0], [0, 0, 1]]); pitch is a rotation about the orbit normal and
/// keeps the motion planar. Its 3-1-3 angles (φ, θ, ψ): C = R3(ψ) R1(θ) R3(φ).

#include "newtop/model/attitude.hpp"
#include "newtop/orbit/orbit_model.hpp"

namespace newtop {

/// C(body←LVLH) of a state: the columns n × γ, −n, −γ (body components).
Mat3 lvlh_to_body(const OrbitState& s);

/// The Euler parameters of C(body←LVLH) as an Eigen quaternion (w = q0 ≥ 0): the rotation whose
/// matrix is Cᵀ (it carries the LVLH axes onto the body axes, in LVLH components).
Quaternion lvlh_quaternion(const Mat3& body_from_lvlh);

/// (roll, pitch, yaw) of C(body←LVLH) = R1(roll) R2(pitch) R3(yaw); pitch in [−π/2, π/2], roll
/// and yaw in (−π, π].
Vec3 roll_pitch_yaw(const Mat3& body_from_lvlh);
/// C(body←LVLH) = R1(roll) R2(pitch) R3(yaw).
Mat3 body_from_roll_pitch_yaw(const Vec3& roll_pitch_yaw);

/// (φ, θ, ψ) of C(body←LVLH) = R3(ψ) R1(θ) R3(φ); θ in [0, π].
Vec3 lvlh_euler_313(const Mat3& body_from_lvlh);

/// The frame rotation R_i(a) about axis i (0, 1, 2): the components in a frame turned by a about
/// e_i of a vector given in the original frame.
Mat3 frame_rotation(int axis, double angle);

}  // namespace newtop
