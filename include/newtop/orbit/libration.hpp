#pragma once
/// \file
/// Planar pitch motion on an elliptic orbit (docs/orbit.md §4 and §9): Beletsky's equation in the
/// true anomaly ν,
///   (1 + e cos ν) θ″ − 2e sin ν (θ′ + 1) + 3k sin θ cos θ = 0,   k = (B − A)/C,
/// θ the angle about the orbit normal (body z, moment C) from the radius to the body x axis
/// (moment A), ′ = d/dν. With x = (θ, θ′) its variational equation is
///   δx′ = [[0, 1], [−3k cos 2θ / (1 + e cos ν), 2e sin ν / (1 + e cos ν)]] δx,
/// whose trace integrates to Liouville's det Φ(ν1, ν0) = ((1 + e cos ν0)/(1 + e cos ν1))².
/// Both are integrated together by Fehlberg 7(8) (Boost.Odeint) at a tight tolerance.

#include <Eigen/Core>

#include "newtop/model/body.hpp"
#include "newtop/orbit/orbit.hpp"
#include "newtop/orbit/orbit_model.hpp"

namespace newtop {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

/// The two numbers of Beletsky's equation: e and k = (B − A)/C.
struct PitchProblem {
  double eccentricity = 0.0;  ///< e, 0 ≤ e < 1
  double k = 0.0;             ///< (B − A)/C, −1 < k < 1 for a physical body
};

/// Checked: 0 ≤ e < 1 and k finite (InputError naming `eccentricity` / `k` otherwise).
PitchProblem pitch_problem(double eccentricity, double k);

/// The pitch problem of a body on an ellipse: k from the principal moments (A, B, C); throws
/// InputError unless the body turns about its centre of mass without gyrostatic moment (the
/// planar motion about z is Beletsky's equation only then).
/// The body and a state relabelled so that the principal axis along the orbit normal is z: the
/// axes turned by the signed permutation P (a rotation, det P = 1) with P n = e_z for the axis a
/// of largest |n_a| (rows of P: e_{a+1}, σ e_{a+2}, σ e_a with σ the sign of n_a), the moments
/// reordered alike. The motion is the same; Beletsky's equation then holds with A, B the moments
/// of the new x, y axes and C that of the pitch axis, whichever body axis it is.
struct PitchFrame {
  Body body;
  OrbitState state;
  int pitch_axis = 2;  ///< the body axis along ±n (0, 1, 2)
};
PitchFrame pitch_frame(const Body& body, const OrbitState& s);

PitchProblem pitch_problem(const Body& body, const EllipticOrbit& orbit);

/// (θ, θ′) of a planar state at the true anomaly ν: the orbit normal along body z, γ in the body
/// xy plane and ω along z, each within `tolerance`; θ = atan2(−γ_y, γ_x) (γ = (cos θ, −sin θ, 0))
/// and θ′ = ω_z/ν̇ − 1. Throws InputError naming `initial` otherwise.
Vec2 pitch_state(const Body& body, const EllipticOrbit& orbit, const OrbitState& s, double nu,
                 double tolerance);

/// Absolute and relative tolerance of the Fehlberg 7(8) steps of every pitch integration.
inline constexpr double kPitchTolerance = 1e-13;

/// x′ = (θ′, [2e sin ν (θ′ + 1) − 3k sin θ cos θ] / (1 + e cos ν)) at x = (θ, θ′).
Vec2 beletsky_rhs(const PitchProblem& p, const Vec2& x, double nu);

/// The variational matrix A(ν, θ) with δx′ = A δx.
Mat2 beletsky_jacobian(const PitchProblem& p, const Vec2& x, double nu);

/// x(ν1) from x(ν0) = x0 (ν1 < ν0 allowed).
Vec2 pitch_advance(const PitchProblem& p, const Vec2& x0, double nu0, double nu1);

/// x(ν1) and the fundamental matrix Φ(ν1, ν0) = ∂x(ν1)/∂x(ν0).
struct PitchFlow {
  Vec2 x;
  Mat2 phi;
};
PitchFlow pitch_flow(const PitchProblem& p, const Vec2& x0, double nu0, double nu1);

/// Liouville's formula: det Φ(ν1, ν0) = ((1 + e cos ν0)/(1 + e cos ν1))², 1 over whole orbits.
double liouville_determinant(double eccentricity, double nu0, double nu1);

}  // namespace newtop
