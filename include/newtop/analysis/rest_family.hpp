#pragma once
/// \file
/// The equilibria at rest of the fixed-point model in the quadratic field continued in one
/// parameter of the body or the field (docs/continuation.md §4b).

#include <functional>
#include <string>

#include "newtop/analysis/continuation.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// The model at the parameter value p.
using QuadraticPath = std::function<QuadraticModel(double p)>;

/// `base` with one scenario key set to p: `body.inertia[i]`, `body.center_of_mass[i]` (i = 0, 1,
/// 2), `body.mass`, `field.g` or `field.lambda`; the body is rebuilt by its checked factory (so
/// the path throws InputError where p forms no body). InputError for another key.
QuadraticPath quadratic_path(const QuadraticModel& base, const std::string& key);

/// The equilibrium at rest (ω = 0) near γ0 along the path from p0 to p1 (docs/model.md §7): the
/// unknowns (γ, κ), the residuals b + λIγ − κγ (b = M g r0) and (γ·γ − 1)/2, the Jacobian
/// [λI − κE, −γ; γᵀ, 0] with F_p by a central difference. FamilyPoint: values (γ_x, γ_y, γ_z,
/// κ), the four leaf eigenvalues (linear_stability at m = 0), stability as to_string(
/// EquilibriumType) of make_equilibrium (`minimum` is Lyapunov stable); tests: the branch-point
/// determinant det [F_u F_p; tᵀ] (branch_point: another family of equilibria crosses, as where
/// an off-axis pair merges into an axis, a pitchfork) besides the fold (dp/ds: two equilibria
/// collide and vanish, a saddle-node). InputError for a body with a gyrostatic moment, or when
/// γ0 is not within 1e-6 of an equilibrium at p0.
Family rest_family(const QuadraticPath& path, const Vec3& gamma0, double p0, double p1,
                   const ContinuationSettings& settings = {});

}  // namespace newtop
