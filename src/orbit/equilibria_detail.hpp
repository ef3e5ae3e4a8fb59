#pragma once
// Internal pieces of the relative-equilibrium search (src/orbit/orbit_equilibria.cpp and
// src/orbit/gyrostat_resultant.cpp); docs/orbit.md §6 derives every formula.

#include <vector>

#include "newtop/core/types.hpp"

namespace newtop::orbit_detail {

/// The problem in units of the largest moment: I/I_max, h = k/(ω0 I_max) with components below
/// kOrbitEquilibriumDegeneracy set to 0, ε = λ/ω0², κ = 1 + 1/ε.
struct EquilibriumProblem {
  Vec3 I;
  Vec3 h;
  double eps;
  double kappa;
};

/// A candidate orientation (γ, n), not yet verified.
struct Orientation {
  Vec3 gamma;
  Vec3 normal;
};

/// The two orientations of the multiplier solution with amplitudes ξ: S_j = Σ ξ_i² I_i^j,
/// a = ε S1/S0, c = ±1/√S0, γ = −c ξ, n_i = −(ε I_i − a) ξ_i.
void add_from_amplitudes(const EquilibriumProblem& pb, const Vec3& xi,
                         std::vector<Orientation>& out);

/// The branch with every active Δ_i ≠ 0 over the active axes (|active| = 2 or 3): the real
/// roots p of the resultant of the plane cubic Σ h_i²/Δ_i = κ and quartic
/// ε²(S0 S2 − S1²) = S0 in (p, q), Δ_i = ε I_i² + p I_i + q. Returns the resultant's Chebyshev
/// tail (relative), see RelativeEquilibriumSet::resultant_tail.
double solve_free_branch(const EquilibriumProblem& pb, const std::vector<int>& active,
                         std::vector<Orientation>& out);

}  // namespace newtop::orbit_detail
