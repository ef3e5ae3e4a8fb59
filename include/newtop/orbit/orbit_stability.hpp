#pragma once
/// \file
/// Linear stability of relative equilibria on a circular orbit (docs/orbit.md §7): the Jacobian
/// of the (m, γ, n) equations reduced to the symplectic leaf of the three Casimirs, its
/// characteristic polynomial, and the energy–Casimir (Jacobi integral) test.

#include <complex>
#include <vector>

#include "newtop/orbit/orbit_model.hpp"

namespace newtop {

using OrbitJacobian = Eigen::Matrix<double, 9, 9>;
using OrbitLeafBasis = Eigen::Matrix<double, 9, 6>;
using OrbitReduced = Eigen::Matrix<double, 6, 6>;

/// Jacobian of rhs(model, ·) with respect to x = (m, γ, n), with [a]× v = a × v:
/// [[ [m]× I⁻¹ − [ω]×,  λ([γ]× I − [Iγ]×),  0 ],
///  [ [γ]× I⁻¹,        −[ω]× + ω0 [n]×,     −ω0 [γ]× ],
///  [ [n]× I⁻¹,        0,                   −[ω]× ]].
OrbitJacobian jacobian(const CircularOrbitModel& model, const OrbitState& s);

/// Jacobian of rhs(model, ·, ν) on an elliptic orbit: σ(ν) times the circular Jacobian with
/// ω0 = 0 and λ(ν), plus the orbital rotation's [n]× in (γ, γ) and −[γ]× in (γ, n).
OrbitJacobian jacobian(const EllipticOrbitModel& model, const OrbitState& s, double nu);

/// Orthonormal basis of the tangent space of the leaf through s: the δx orthogonal to the
/// gradients of γ·γ/2 (0, γ, 0), n·n/2 (0, 0, n) and γ·n (0, n, γ).
OrbitLeafBasis leaf_basis(const OrbitState& s);

/// Qᵀ J Q with Q = leaf_basis(s). At a fixed point ∇C·J = 0 for each Casimir, so the nine
/// eigenvalues of J are the six of Qᵀ J Q and three exact zeros (the Casimir directions).
OrbitReduced reduced_jacobian(const CircularOrbitModel& model, const OrbitState& s);

/// Relative residual of the fixed-point condition rhs(s) = 0:
/// |ṁ| / (|m||ω| + |λ| max I) + |γ̇| / (|ω| + ω0) + |ṅ| / |ω| (a term is 0 when its scale is 0).
double fixed_point_residual(const CircularOrbitModel& model, const OrbitState& s);

/// A state counts as a relative equilibrium when its residual is below this: values copied with
/// 12 or more significant digits pass.
inline constexpr double kRelativeEquilibriumTolerance = 1e-9;

/// State at rest in the orbital frame with the given γ and n: ω = ω0 n, m = ω0 I n + k.
OrbitState relative_rest_state(const CircularOrbitModel& model, const Vec3& gamma,
                               const Vec3& normal);

/// Coefficients of det(s E − Qᵀ J Q), constant term first (degree 6, leading 1). The spectrum of
/// a Hamiltonian system is symmetric under s → −s: the odd coefficients vanish up to round-off.
Eigen::Matrix<double, 7, 1> characteristic_polynomial(const CircularOrbitModel& model,
                                                      const OrbitState& s);

/// Second variation of F = H + μ1 γ·γ/2 + μ2 n·n/2 + μ3 γ·n on the leaf's tangent space at a
/// relative equilibrium (μ fixed by dF = 0): μ1 = −λ γ·Iγ, μ2 = ω0 m·n, μ3 = −λ n·Iγ.
/// Positive definite ⇒ Lyapunov stable (the Jacobi integral has a strict minimum on the leaf).
OrbitReduced energy_casimir_hessian(const CircularOrbitModel& model, const OrbitState& s);

/// A real part below this fraction of |Qᵀ J Q| counts as zero: Jordan blocks of size 2 at
/// stability boundaries are resolved only to ~√ε ≈ 1.5e-8; 1e-6 stays clear of that.
inline constexpr double kOrbitSpectralTolerance = 1e-6;

/// Verdict on a relative equilibrium.
enum class OrbitStability {
  lyapunov,    ///< energy–Casimir definite: the Jacobi integral is a strict minimum (Lagrange)
  gyroscopic,  ///< spectrally stable but indefinite: stable by gyroscopic coupling (DeBra–Delp)
  unstable,    ///< an eigenvalue with a positive real part
};

/// "lyapunov", "gyroscopic" or "unstable".
const char* to_string(OrbitStability v);

struct RelativeSpectrum {
  std::vector<std::complex<double>> eigenvalues;  ///< the six leaf eigenvalues, sorted
  Eigen::Matrix<double, 7, 1> characteristic;     ///< characteristic_polynomial
  double max_real_part = 0.0;
  bool linearly_stable = false;  ///< every real part within kOrbitSpectralTolerance·|QᵀJQ| of 0
  bool energy_casimir_definite = false;
  OrbitStability verdict = OrbitStability::unstable;
};

/// Eigenvalues, characteristic polynomial and verdict at a relative equilibrium (callers taking
/// user input check fixed_point_residual ≤ kRelativeEquilibriumTolerance first).
RelativeSpectrum relative_equilibrium_stability(const CircularOrbitModel& model,
                                                const OrbitState& s);

}  // namespace newtop
