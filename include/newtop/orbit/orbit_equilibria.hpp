#pragma once
/// \file
/// Relative equilibria on a circular orbit (docs/orbit.md §6): the body at rest in the orbital
/// frame, ω = ω0 n, m = ω0 I n + k. They are the critical points on SO(3) of the amended
/// potential W/ω0² = (ε/2) γ·Iγ − ½ n·In − h·n, with ε = λ/ω0² (3 on a Kepler orbit) and
/// h = k/ω0. For a triaxial body (k = 0) they are the 24 orientations with the principal axes
/// along the orbital axes; for a gyrostat there are between 8 and 24 (Sarychev & Gutnik), found
/// here by a polynomial route: the Lagrange multipliers reduce the problem to a plane cubic and a
/// plane quartic in two multipliers (p, q), whose resultant — a polynomial of degree 12 — is
/// interpolated exactly and solved by a colleague-matrix eigenvalue problem; components of h that
/// vanish add closed-form branches.

#include <vector>

#include "newtop/orbit/orbit_stability.hpp"

namespace newtop {

/// One relative equilibrium.
struct RelativeEquilibrium {
  Vec3 gamma;       ///< unit vector centre → body, body axes
  Vec3 normal;      ///< orbit normal n, body axes
  double jacobi;    ///< the Jacobi integral there
  double residual;  ///< fixed_point_residual of relative_rest_state(γ, n)
  RelativeSpectrum stability;
};

/// All relative equilibria of a model.
struct RelativeEquilibriumSet {
  std::vector<RelativeEquilibrium> equilibria;  ///< by increasing Jacobi integral
  int lyapunov = 0, gyroscopic = 0, unstable = 0;
  /// Candidates from the polynomial route whose fixed-point residual exceeded
  /// kRelativeEquilibriumTolerance (dropped; 0 unless the route lost accuracy).
  int unverified = 0;
  /// The resultant's Chebyshev coefficients above its degree, relative to the largest: the
  /// interpolant is the degree-12 (or 4) polynomial when this is at round-off (0 when the
  /// resultant was not needed).
  double resultant_tail = 0.0;
  /// The largest distance (max norm of γ and n) by which the final Newton polish on SO(3) moved a
  /// listed equilibrium from the polynomial route's candidate: the route's own accuracy (~1e-12,
  /// ~√ε where two equilibria are about to be born). The polish cannot hide an error of the
  /// route: a large value here is one.
  double polish_distance = 0.0;
};

/// Relative size below which a component of h = k/ω0 (relative to the largest moment) counts as
/// zero, and two principal moments as equal.
inline constexpr double kOrbitEquilibriumDegeneracy = 1e-12;

/// Every relative equilibrium of a body with distinct principal moments on a circular orbit with
/// ω0 > 0 and λ > 0, each checked as a fixed point (residual) and classified
/// (relative_equilibrium_stability). Throws InputError for equal moments (the equilibria then form
/// continuous families) and for ω0 = 0 or λ ≤ 0.
RelativeEquilibriumSet find_relative_equilibria(const CircularOrbitModel& model);

}  // namespace newtop
