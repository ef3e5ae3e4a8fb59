#pragma once
/// \file
/// Stability of equilibria and permanent rotations (fixed points of the Euler–Poisson equations,
/// docs/model.md §7–§9): linearisation reduced to the symplectic leaf, energy–Casimir test,
/// Beletsky's threshold for the spin about the radius vector.

#include <complex>
#include <optional>
#include <vector>

#include "newtop/model/model.hpp"

namespace newtop {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using LeafBasis = Eigen::Matrix<double, 6, 4>;

/// Jacobian of rhs(model, ·) with respect to x = (m, γ) (docs/model.md §4):
/// [[ [m]× I⁻¹ − [ω]×,  ∂L/∂γ ], [ [γ]× I⁻¹,  −[ω]× ]], with [a]× v = a × v and ∂L/∂γ =
/// [γ]× ∂²V/∂γ² − [∂V/∂γ]× the moment Jacobian of the model's own field (λI for ∂²V/∂γ² in the
/// quadratic field).
Mat6 jacobian(const Model& model, const State& s);

/// Orthonormal basis of the tangent space of the symplectic leaf through s: the vectors δx with
/// ∇C·δx = 0 for both Casimirs C1 = ½ γ·γ (gradient (0, γ)) and C2 = m·γ (gradient (γ, m)).
LeafBasis leaf_basis(const State& s);

/// Linearisation on the leaf, Qᵀ J Q with Q = leaf_basis(s). At a fixed point ∇C·J = 0, so J maps
/// ℝ⁶ into the leaf's tangent space; the six eigenvalues of J are those of Qᵀ J Q plus two exact
/// zeros (the Casimir directions), which this reduction discards.
Eigen::Matrix4d reduced_jacobian(const Model& model, const State& s);

/// Relative residual of the fixed-point condition rhs(s) = 0:
/// |ṁ| / (|m||ω| + |∂V/∂γ|) + |γ̇| / |ω| (each term 0 when its scale is 0). 0 exactly at an
/// equilibrium or permanent rotation, at most about 2 anywhere on the unit sphere.
double fixed_point_residual(const Model& model, const State& s);

/// A state counts as a fixed point when its residual is below this: values copied with 12 or more
/// significant digits from `newtop equilibria` / `newtop rotations` pass.
inline constexpr double kFixedPointTolerance = 1e-9;

/// A fixed point given to a few digits (e.g. copied from `newtop equilibria`) is polished by
/// polish_fixed_point; a correction larger than this (|δγ|, and |δm| relative to |m|) means the
/// state given was not a fixed point to three digits, and Newton's method may have found another.
inline constexpr double kPolishRadius = 1e-3;

/// A fixed point recovered from an approximation by polish_fixed_point.
struct PolishedFixedPoint {
  State state;                  ///< the polished state (the one given when no step improved it)
  double residual_given = 0.0;  ///< fixed_point_residual of the state given
  double residual = 0.0;        ///< fixed_point_residual of `state`
  /// max(|γ − γ_given|, |m − m_given| / |m_given|) (the second term only when ω_given ≠ 0).
  double correction = 0.0;
  int iterations = 0;  ///< Newton steps taken
  /// residual ≤ kFixedPointTolerance and correction ≤ kPolishRadius.
  bool converged = false;
};

/// Newton's method (least-norm Gauss–Newton steps, SVD) for the fixed point of the Euler–Poisson
/// equations nearest to s (docs/model.md §7, §8): rhs(m, γ) = 0 with |γ| = 1. A state at rest (ω =
/// 0) stays at rest and only γ moves (γ × ∂V/∂γ = 0); otherwise m and γ both move, the step of
/// least norm in (m/|m|, γ), so that a spin keeps its Ω where the fixed points form a family in Ω.
/// Stops when the residual (plus ||γ| − 1|) stops decreasing, after at most 50 steps.
PolishedFixedPoint polish_fixed_point(const Model& model, const State& s);

/// A real part below this fraction of the reduced Jacobian's norm counts as zero. A non-trivial
/// Jordan block of size 2 (the degenerate spectra at stability boundaries) is resolved by the
/// eigenvalue solver only to ~sqrt(eps) ≈ 1.5e-8 relative; 1e-6 stays clear of that.
inline constexpr double kSpectralTolerance = 1e-6;

/// Linear analysis of a fixed point.
struct Spectrum {
  std::vector<std::complex<double>> eigenvalues;  ///< the four leaf eigenvalues, sorted
  double max_real_part = 0.0;
  /// Spectrally stable: every real part within kSpectralTolerance · |J| of zero (Hamiltonian
  /// spectra are symmetric under s → −s, so this means a purely imaginary spectrum).
  bool linearly_stable = false;
  /// true: the energy–Casimir test proves Lyapunov stability; false: linearly unstable (hence
  /// unstable); nullopt: spectrally stable but the sufficient test is inconclusive.
  std::optional<bool> lyapunov_stable;
};

/// Second variation of the energy–Casimir function F = H − Ω C2 + ν C1 on the leaf's tangent
/// space, at a fixed point with ω = Ω γ (ω = 0 at rest), ν fixed by dF = 0. Positive definite ⇒
/// Lyapunov stable (Arnold; Holm–Marsden–Ratiu–Weinstein).
Eigen::Matrix4d energy_casimir_hessian(const Model& model, const State& s);

/// True when energy_casimir_hessian is positive definite (its least eigenvalue above
/// kSpectralTolerance times its norm).
bool energy_casimir_stable(const Model& model, const State& s);

/// Eigenvalues on the leaf, verdicts. Requires a fixed point (fixed_point_residual ≤
/// kFixedPointTolerance; checked by callers that take user input).
Spectrum linear_stability(const Model& model, const State& s);

}  // namespace newtop
