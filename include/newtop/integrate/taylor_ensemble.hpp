#pragma once
/// \file
/// The Taylor ensemble: many trajectories of the quadratic field (docs/model.md §3, §4), each on
/// its own model, integrated by Taylor's method (taylor.hpp) in SIMD lanes, one trajectory per lane
/// (AVX-512: 8 doubles, AVX2: 4, portable: 2; the instruction set chosen at run time as for the
/// splitting ensemble, ensemble.hpp). One order for the batch (taylor_order of the tolerance),
/// a step per lane from that lane's own coefficients; a lane whose trajectory reaches t1 takes
/// the next trajectory waiting.
///
/// Guarantee: every trajectory's Outcome, observed steps and samples are bit-identical to those of
/// the adaptive driver (driver.hpp, sampled.hpp) running TaylorStepper(abs_tol, rel_tol) on that
/// trajectory alone, whatever its lane, the batch size or the instruction set. Each lane performs
/// the scalar recurrences' operations (taylor.cpp) in the same order on its own numbers, without
/// fused multiply-adds, and the step rule's (newtop's own log2 and exp2, taylor_step_log2 and
/// taylor_step_exp2); each lane's step, acceptance and end are the driver's, decided by the same
/// scalar code (tests/integrate/test_taylor_ensemble.cpp checks it).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "newtop/integrate/ensemble.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/integrate/outcome.hpp"
#include "newtop/integrate/output_times.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// What a Taylor ensemble reports besides the outcomes, trajectory by trajectory (each call names
/// the trajectory by its position in the batch; the calls of one trajectory come in its order, the
/// trajectories interleaved).
struct TaylorEnsembleObserver {
  /// Called at t0 and after every accepted step with (point, t, state), as a step observer of the
  /// driver.
  std::function<void(std::size_t point, double t, const State& x)> step;
  /// With `times`: called at each output time t_k with (point, k, t_k, state), the state from the
  /// series of the step that contains t_k, as integrate_sampled reports it.
  const OutputTimes* times = nullptr;
  std::function<void(std::size_t point, std::int64_t k, double t, const State& x)> sample;
};

/// A tangent vector (δm, δγ) of a trajectory.
using TangentVector = Eigen::Matrix<double, 6, 1>;

/// Called after every accepted step of a tangent run with (point, t, state, tangent vector); it
/// may change the vector (a renormalisation), which the run then carries on.
using TaylorTangentObserver =
    std::function<void(std::size_t point, double t, const State& x, TangentVector& v)>;

/// Taylor's method on many trajectories at once (see the file's comment for the guarantee).
/// Holds a workspace: one ensemble per thread.
class TaylorEnsemble {
 public:
  /// Throws InputError as TaylorStepper does for the tolerances and the order, and if the path is
  /// not available. `order`: as TaylorStepper's (0: taylor_order of the smaller tolerance); the
  /// guarantee holds against TaylorStepper(abs_tol, rel_tol, order).
  TaylorEnsemble(double abs_tol, double rel_tol, SimdPath path = best_simd_path(), int order = 0);

  int order() const { return order_; }
  SimdPath path() const { return path_; }
  double abs_tol() const { return abs_tol_; }
  double rel_tol() const { return rel_tol_; }
  /// The number of trajectories advanced together.
  std::size_t lanes() const;

  /// Integrates trajectory i from (t0, states[i]) to t1 on models[i] (or models[0] for all when
  /// one model is given), with the options of the adaptive driver. Throws InputError before any
  /// work for bad times, options or states (as integrate() does) and for a number of models other
  /// than 1 or states.size().
  std::vector<Outcome> integrate(std::span<const QuadraticModel> models,
                                 std::span<const State> states, double t0, double t1,
                                 const IntegrateOptions& options = {},
                                 const TaylorEnsembleObserver& observer = {});

  /// The same with one tangent vector per trajectory (v0[i], or v0[0] for all), carried by the
  /// variational equations: each trajectory's Outcome and observed steps are those of
  /// integrate_tangent_adaptive (newtop/phase/chaos_run.hpp) with TangentTaylorStepper(abs_tol,
  /// rel_tol) and that vector alone, bit for bit (the step from the state's and the vector's
  /// coefficients together, as there).
  std::vector<Outcome> integrate_tangent(std::span<const QuadraticModel> models,
                                         std::span<const State> states,
                                         std::span<const TangentVector> v0, double t0, double t1,
                                         const IntegrateOptions& options,
                                         const TaylorTangentObserver& observer);

 private:
  double abs_tol_, rel_tol_;
  int order_;
  SimdPath path_;
  std::vector<double> workspace_;
};

}  // namespace newtop
