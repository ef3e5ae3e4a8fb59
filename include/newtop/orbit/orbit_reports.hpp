#pragma once
/// \file
/// The orbit analyses behind `newtop stability` on an orbit scenario and `newtop stability
/// --diagram debra-delp`, as results (docs/orbit.md §7–§8): the stability of one relative
/// equilibrium chosen by its number or given as a state, and the DeBra–Delp diagram on a grid
/// with its counts and its comparison with the closed form. The program, Python and C++ callers
/// share them, so the same input is refused with the same words everywhere.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "newtop/orbit/debra_delp.hpp"
#include "newtop/orbit/orbit_stability.hpp"

namespace newtop {

/// Which relative equilibrium: exactly one of `equilibrium` (1-based, in the order of
/// find_relative_equilibria) and `state`.
struct RelativeStabilityRequest {
  std::optional<int> equilibrium;
  std::optional<OrbitState> state;
  /// How errors name the two (the program names its option and the scenario's [initial]).
  std::string equilibrium_name = "equilibrium";
  std::string state_name = "state";
};

/// The linear stability of a relative equilibrium and where it was taken.
struct RelativeStabilityReport {
  RelativeSpectrum spectrum;
  OrbitState state;     ///< the equilibrium (relative_rest_state for a numbered one)
  Vec3 omega;           ///< ω there, body axes
  double jacobi = 0;    ///< the Jacobi integral there
  double residual = 0;  ///< fixed_point_residual (≤ kRelativeEquilibriumTolerance)
};

/// Throws InputError for neither or both of equilibrium and state, a number outside 1…count, or a
/// state whose fixed-point residual exceeds kRelativeEquilibriumTolerance.
RelativeStabilityReport relative_stability(const CircularOrbitModel& model,
                                           const RelativeStabilityRequest& request);

/// One axis of the diagram's grid: n values from lo to hi, ends included.
struct RatioRange {
  double lo = -0.99, hi = 0.99;
  int n = 67;
};

/// The DeBra–Delp diagram on a grid (row by row, k_R outer).
struct DebraDelpDiagram {
  std::vector<DebraDelpPoint> points;
  /// Points per computed region, in the order lagrange, debra_delp, unstable.
  std::array<int, 3> counts{};
  /// Points off every boundary whose computed region differs from the closed form's.
  int disagreements_with_closed_form = 0;
};

/// debra_delp_scan's checks (counts ≥ 1, every point inside |k| < 1).
DebraDelpDiagram debra_delp_diagram(const RatioRange& k_R = {}, const RatioRange& k_Y = {});

}  // namespace newtop
