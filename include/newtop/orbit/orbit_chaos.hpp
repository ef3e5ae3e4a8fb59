#pragma once
/// \file
/// Chaos indicators on an orbit (docs/orbit.md §13): the maximal Lyapunov exponent, the spectrum,
/// MEGNO and the FLI of the orbit model, from its variational equations
/// δx′ = J(x) δx (J the Jacobian of rhs, orbit_stability.hpp) integrated beside (m, γ, n) by an
/// embedded Runge–Kutta pair or by Taylor's method (the variational recurrences of
/// orbit_taylor.hpp) on the engine's one driver (integrate/driver.hpp), the tangent vectors
/// renormalised after every accepted step (phase/chaos.hpp accumulates the indicators).
///
/// The tangent vectors start on the symplectic leaf of the Casimirs (leaf_basis) and stay on it:
/// the spectrum is the six exponents of the leaf, which a Hamiltonian flow pairs as ±λ (the
/// Jacobi integral on a circular orbit; H_ν on an ellipse). On an elliptic orbit the run is in
/// the true anomaly ν and the indicators are per unit time (t(ν) by Kepler's equation).

#include <cstdint>
#include <functional>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "newtop/phase/chaos.hpp"

namespace newtop {

/// What a chaos run on an orbit does (one struct, no positional list).
struct OrbitChaosSettings {
  /// A method with its tolerances: rkf78, dopri5, dop853 or taylor (the variational equations
  /// are integrated by it; a splitting composition is refused).
  MethodSettings method;
  double t0 = 0.0;  ///< start time
  double t1 = 0.0;  ///< end time (> t0; in time on an ellipse too)
  bool spectrum = false;
  std::int64_t max_steps = 100'000'000;
  /// Receives a sample every `every` accepted steps (and the last).
  std::function<void(const phase::ChaosSample&)> history;
  std::int64_t every = 1;
  /// Called after every accepted step with the time (throws to stop the run).
  std::function<void(double)> on_step;
};

struct OrbitChaosResult {
  OrbitOutcome outcome;  ///< in the run's variable (t, or ν on an ellipse)
  double t = 0.0;        ///< the time reached
  phase::ChaosSample indicators;
};

/// Throws InputError naming `method` unless it is one of the orbit's adaptive methods with
/// tolerances > 0, and naming `t_end` unless t1 > t0 (both finite).
void check_orbit_chaos_settings(const OrbitChaosSettings& settings);

OrbitChaosResult orbit_chaos(const CircularOrbitModel& model, const OrbitState& x0,
                             const OrbitChaosSettings& settings);
/// On an ellipse x0 is the state at ν0 = orbit().true_anomaly0, reached at settings.t0.
OrbitChaosResult orbit_chaos(const EllipticOrbitModel& model, const OrbitState& x0,
                             const OrbitChaosSettings& settings);

namespace detail {
/// The step of a chaos run's one tangent vector after each accepted step (shared with the orbit's
/// Taylor ensemble): v projected on the tangent space of x's symplectic leaf and renormalised to
/// unit length; returns the log of the factor it shrank by.
double orbit_leaf_renormalise(const OrbitState& x, Eigen::Matrix<double, 9, 1>& v);
/// The start of a chaos run's one tangent vector: the sum of the leaf's six basis vectors / √6.
Eigen::Matrix<double, 9, 1> orbit_chaos_start(const OrbitState& x0);
}  // namespace detail

/// The tangent map Φ = ∂x(b)/∂x(a) of the flow from a to b (t, or ν on an ellipse), from the
/// variational equations with the named method, unrenormalised (for checks against finite
/// differences of the flow).
Eigen::Matrix<double, 9, 9> orbit_tangent_map(const MethodSettings& method,
                                              const CircularOrbitModel& model, const OrbitState& x,
                                              double a, double b);
Eigen::Matrix<double, 9, 9> orbit_tangent_map(const MethodSettings& method,
                                              const EllipticOrbitModel& model, const OrbitState& x,
                                              double a, double b);

}  // namespace newtop
