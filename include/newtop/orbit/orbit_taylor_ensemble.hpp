#pragma once
/// \file
/// The orbit's Taylor ensemble: many trajectories of a satellite on a circular or an elliptic
/// orbit (docs/orbit.md §5), each on its own model, integrated by Taylor's method
/// (orbit_taylor.hpp) with the recurrences in SIMD lanes, one trajectory per lane (AVX-512: 8
/// doubles, AVX2: 4, portable: 2; chosen at run time as for the other ensembles,
/// newtop/integrate/ensemble.hpp). One order for the batch, a step per lane from that lane's own
/// coefficients; a lane whose trajectory reaches its end takes the next trajectory waiting.
///
/// Guarantee: every trajectory's OrbitOutcome and observed steps are bit-identical to those of the
/// adaptive driver running OrbitTaylorStepper(abs_tol, rel_tol, order) on that trajectory alone
/// (run_orbit_method with method taylor, given its options), whatever its lane, the batch size or
/// the instruction set: each lane performs orbit_taylor_expand's operations in the same order on
/// its own numbers, without fused multiply-adds, and each lane's step rule, sum of the series,
/// acceptance and end are the scalar stepper's and the driver's, by the same code
/// (tests/orbit/test_orbit_taylor_ensemble.cpp checks it).

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "newtop/integrate/ensemble.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "newtop/orbit/orbit_model.hpp"

namespace newtop {

/// Called at the start and after every accepted step with (point, t or ν, state), as the driver's
/// step observer of that trajectory (the calls of one trajectory in its order, the trajectories
/// interleaved).
using OrbitEnsembleObserver = std::function<void(std::size_t point, double t, const OrbitState&)>;

/// A tangent vector (δm, δγ, δn) of an orbit trajectory.
using OrbitVector = Eigen::Matrix<double, 9, 1>;

/// Called after every accepted step of a chaos run with (point, t or ν, state, log of the factor by
/// which the step's renormalisation shrank the tangent vector).
using OrbitChaosObserver =
    std::function<void(std::size_t point, double t, const OrbitState&, double log_growth)>;

/// Taylor's method on many orbit trajectories at once (see the file's comment for the guarantee).
/// Holds a workspace: one ensemble per thread.
class OrbitTaylorEnsemble {
 public:
  /// Throws InputError as OrbitTaylorStepper does for the tolerances and the order, and if the
  /// path is not available.
  OrbitTaylorEnsemble(double abs_tol, double rel_tol, SimdPath path = best_simd_path(),
                      int order = 0);

  int order() const { return order_; }
  SimdPath path() const { return path_; }
  /// The number of trajectories advanced together.
  std::size_t lanes() const;

  /// Integrates trajectory i from (t0, states[i]) to t1 on models[i] (or models[0] for all when one
  /// model is given), with the adaptive driver's options. Throws InputError before any work for
  /// bad times, options or states (as integrate() does) and for a number of models other than 1 or
  /// states.size().
  std::vector<OrbitOutcome> integrate(std::span<const CircularOrbitModel> models,
                                      std::span<const OrbitState> states, double t0, double t1,
                                      const IntegrateOptions& options = {},
                                      const OrbitEnsembleObserver& observer = {});
  /// The same on ellipses, in the true anomaly, from ν0 to ν1.
  std::vector<OrbitOutcome> integrate(std::span<const EllipticOrbitModel> models,
                                      std::span<const OrbitState> states, double nu0, double nu1,
                                      const IntegrateOptions& options = {},
                                      const OrbitEnsembleObserver& observer = {});

  /// The tangent runs of orbit_chaos (orbit_chaos.hpp) with method taylor and one vector: each
  /// trajectory carries the vector from detail::orbit_chaos_start, the step rule over the state
  /// and the vector, the vector projected on the leaf and renormalised after every accepted step
  /// (detail::orbit_leaf_renormalise), the observer told the log of each factor; each
  /// trajectory's outcome and observed steps are that run's, bit for bit.
  std::vector<OrbitOutcome> integrate_chaos(std::span<const CircularOrbitModel> models,
                                            std::span<const OrbitState> states, double t0,
                                            double t1, const IntegrateOptions& options,
                                            const OrbitChaosObserver& observer);
  std::vector<OrbitOutcome> integrate_chaos(std::span<const EllipticOrbitModel> models,
                                            std::span<const OrbitState> states, double nu0,
                                            double nu1, const IntegrateOptions& options,
                                            const OrbitChaosObserver& observer);

 private:
  double abs_tol_, rel_tol_;
  int order_;
  SimdPath path_;
  std::vector<double> workspace_;
};

}  // namespace newtop
