#pragma once
/// \file
/// The Lyapunov families of the Euler–Poisson equations (docs/continuation.md §4c): periodic
/// orbits born from a normal mode ±iω of a stable equilibrium at rest, continued in the energy.

#include "newtop/analysis/continuation.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// The periodic orbits of `model` (quadratic field, no gyrostat) near the equilibrium at rest
/// γ_eq (m = 0) born from its normal mode `mode` (0: the lower frequency ω of the leaf eigenvalues
/// ±iω, 1: the higher), continued in the energy above the equilibrium's, p = H − H_eq, from p0 > 0
/// to p1. Shooting with the unfolding of Muñoz-Almaraz, Freire, Galán, Doedel & Vanderbauwhede
/// (2003) for the three integrals: unknowns (x0 ∈ ℝ⁶, T, β ∈ ℝ³) and the field
/// f + β0∇H + β1∇C1 + β2∇C2 (a periodic orbit exists only at β = 0); residuals x(T) − x0 (Φ, the
/// unfolding's Ψ and f(x(T)) from the variational equations, Bulirsch–Stoer at 1e-12), the
/// section s·(x0 − x_eq) = 0 (s the mode's eigenvector part orthogonal to the start's),
/// H(x0) − H_eq − p, (γ·γ − 1)/2 and m·γ. The start is x_eq + εa (a the real part of the mode's
/// eigenvector, ε from p0 to second order) with T = 2π/ω. FamilyPoint: values (m, γ at t = 0),
/// period T, the six multipliers (four at 1: the flow and the integrals), stability `stable`
/// (the other pair on the unit circle within 1e-6) or `unstable`; tests: tr Φ − 2 (`flip`: the
/// other pair at −1) and tr Φ − 6 (`branch_point`: the other pair at +1 without a fold), besides
/// the fold. InputError when the equilibrium is not one, not linearly
/// stable, or p0 ≤ 0.
Family lyapunov_family(const QuadraticModel& model, const Vec3& gamma_eq, int mode, double p0,
                       double p1, const ContinuationSettings& settings = {});

/// The leaf eigenvalues ±iω of the stable equilibrium at rest: ω (ascending).
Eigen::Vector2d normal_frequencies(const QuadraticModel& model, const Vec3& gamma_eq);

}  // namespace newtop
