#pragma once
/// \file
/// The attitude in the Lagrange-like case (newtop/analysis/lagrange_case.hpp): its Euler angles.

#include "newtop/analysis/lagrange_case.hpp"
#include "newtop/model/attitude.hpp"

namespace newtop {

/// The Euler angles of the motion (3-1-3, newtop/model/attitude.hpp): body → N is
/// R_z(φ) R_x(θ) R_z(ψ), with N the frame fixed in space whose z axis is the fixed direction e
/// (γ = Rᵀ e) and whose x axis is the line of nodes at t = 0 (φ(0) = 0). Nutation cos θ = γ3, spin
/// ψ as in lagrange_state (γ1 = sin θ sin ψ, γ2 = sin θ cos ψ), precession φ = ∫ (b − β γ3)/(1 −
/// γ3²) dt (from p γ1 + q γ2 = φ̇ sin²θ), by the same quadrature as ψ. Returned as (φ, θ, ψ); needs
/// γ3 ≠ ±1 along the motion.
Vec3 lagrange_euler_angles(const LagrangeCase& s, double t);

}  // namespace newtop
