#pragma once
/// \file
/// The DeBra–Delp diagram of a gravity-gradient satellite on a circular Kepler orbit
/// (docs/orbit.md §8): the stability of the rest orientation with the roll axis along the
/// velocity, the pitch axis along the orbit normal and the yaw axis along the radius, over the
/// inertia ratios k_R = (B − C)/A and k_Y = (B − A)/C, where A, B, C are the roll, pitch and yaw
/// moments (body x, y, z: γ = e_z, n = e_y, velocity n × γ = e_x).
///
/// Linearised in units of ω0 (σ = s²/ω0²), the characteristic polynomial factors as
///   (σ + 3 k_P) (σ² + (1 + 3 k_R + k_R k_Y) σ + 4 k_R k_Y),  k_P = (A − C)/B = (k_R − k_Y)/(1 −
///   k_R k_Y),
/// pitch times roll–yaw (DeBra & Delp 1961; Hughes, Spacecraft Attitude Dynamics, §9.3), whence
///   pitch:    k_R > k_Y;
///   roll–yaw: k_R k_Y > 0 and 1 + 3 k_R + k_R k_Y > 4 √(k_R k_Y).
/// Lagrange region: k_R > k_Y > 0 (B > A > C), the Jacobi integral a minimum: Lyapunov stable.
/// DeBra–Delp region: both conditions with k_R, k_Y < 0: stable by gyroscopic coupling only.

#include <array>
#include <complex>
#include <optional>
#include <vector>

#include "newtop/orbit/orbit_stability.hpp"

namespace newtop {

/// The three regions of the diagram.
enum class DebraDelpRegion {
  lagrange,    ///< stable, Jacobi integral a strict minimum
  debra_delp,  ///< spectrally stable by gyroscopic coupling, Jacobi integral indefinite
  unstable,    ///< an eigenvalue with a positive real part
};

/// "lagrange", "debra_delp" or "unstable".
const char* to_string(DebraDelpRegion r);

/// The region from the closed-form conditions above (a point on a boundary counts as unstable).
DebraDelpRegion debra_delp_closed_form(double k_R, double k_Y);

/// The coefficients (constant term first) of (σ + 3 k_P)(σ² + (1 + 3k_R + k_R k_Y)σ + 4 k_R k_Y)
/// in σ = s²/ω0².
Eigen::Vector4d debra_delp_characteristic(double k_R, double k_Y);

/// The moments (A, B, C) = (roll, pitch, yaw) with B = 1 and the given ratios:
/// A = (1 − k_Y)/(1 − k_R k_Y), C = (1 − k_R)/(1 − k_R k_Y). The triangle inequalities hold
/// exactly on the open square |k_R|, |k_Y| < 1 ((1 ∓ k_R)(1 ± k_Y) ≥ 0); throws InputError
/// naming k_R or k_Y outside it.
Vec3 inertia_from_ratios(double k_R, double k_Y);

/// One point of the diagram: the closed form and the verdict of the model's own linearisation
/// (relative_equilibrium_stability of the rest state on a Kepler orbit with ω0 = 1).
struct DebraDelpPoint {
  double k_R = 0.0, k_Y = 0.0;
  DebraDelpRegion closed_form = DebraDelpRegion::unstable;
  DebraDelpRegion computed = DebraDelpRegion::unstable;
  /// The point lies on a boundary: the cubic in σ formed from `characteristic` has a zero or a
  /// repeated root within kDebraDelpDegeneracy (zero-frequency modes or a Krein collision, where
  /// the linearisation decides nothing); `computed` is then the spectral verdict only.
  bool boundary = false;
  double max_real_part = 0.0;                  ///< in units of ω0
  Eigen::Matrix<double, 7, 1> characteristic;  ///< characteristic_polynomial, in s/ω0
};

/// Relative size of the σ-cubic's constant term or discriminant (against the sum of the
/// magnitudes of their terms) below which a point counts as on a boundary: the coefficients carry
/// errors ~1e-12 (test_debra_delp.cpp), so 1e-9 flags only points within ~1e-9 of a boundary.
inline constexpr double kDebraDelpDegeneracy = 1e-9;

/// The point (k_R, k_Y) of the open square; throws InputError outside it.
DebraDelpPoint debra_delp_point(double k_R, double k_Y);

/// A rectangular grid of n_R × n_Y points (row by row, k_R outer), ends included; every point
/// must lie in the open square |k| < 1. Throws InputError for counts < 1 or points outside.
std::vector<DebraDelpPoint> debra_delp_scan(double k_R_lo, double k_R_hi, int n_R, double k_Y_lo,
                                            double k_Y_hi, int n_Y);

}  // namespace newtop

namespace newtop {

/// One linear libration mode about the rest orientation nearest a state (DeBra–Delp): `pitch`
/// (σ = −3 k_P) or a `roll-yaw` root of σ² + (1 + 3k_R + k_R k_Y)σ + 4 k_R k_Y, σ = s²/ω0².
struct LibrationMode {
  const char* name = "pitch";
  std::complex<double> sigma;  ///< s²/ω0²
  bool oscillating = false;    ///< σ real and < 0: a libration of frequency ω0 √(−σ)
  double frequency = 0.0;      ///< √(−σ) ω0 [rad/time] when oscillating, else 0
  double period = 0.0;         ///< 2π/frequency when oscillating, else 0
};

/// The three modes on a circular orbit of rate ω0 about the rest orientation whose axes are the
/// principal axes nearest the state's: pitch along n, yaw along γ, roll along n × γ (A, B, C
/// their moments, k_R = (B − C)/A, k_Y = (B − A)/C, k_P = (A − C)/B).
std::array<LibrationMode, 3> libration_modes(const Body& body, const OrbitState& s, double rate);

}  // namespace newtop
