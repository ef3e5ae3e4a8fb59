#pragma once
/// \file
/// Sweeps through the ensemble stepper (newtop/integrate/ensemble.hpp): the points of a sweep
/// whose quantities are trajectory results only (final_state, drift) and whose runs share a
/// splitting method and its step, the times and the step limit, in a quadratic field (each point
/// with its own model, held per lane), are advanced together, in SIMD lanes; those of a sweep of
/// megno and lyapunov_max only through the ensemble tangent stepper
/// (newtop/phase/ensemble_tangent.hpp) with one tangent vector each; those of final_state and
/// drift run with a tolerance (method taylor) through the Taylor ensemble
/// (newtop/integrate/taylor_ensemble.hpp), a model per lane. Each point's result is
/// bit-identical to evaluate_point's (the ensemble steppers reproduce the scalar steppers bit for
/// bit and the runs follow the fixed-step drivers), so a sweep's output does not depend on which
/// points were grouped, nor on the threads or ranks.

#include <cstddef>
#include <span>
#include <vector>

#include "newtop/sweep/sweep.hpp"

namespace newtop::sweep {

/// Whether run_sweep hands the sweep's points to evaluate_points in batches: every quantity is
/// final_state or drift, or every quantity is megno or lyapunov_max.
bool ensemble_sweep(const SweepFile& s);

/// The results of the points `indices`, in that order, each bit-identical to
/// evaluate_point_safely(s, index): the points of the quadratic field with a finite initial state
/// that share their run's settings (splitting method and step, or taylor and its tolerances; t0,
/// t_end, max_steps), four or more,
/// are advanced together by the ensemble stepper, each on its own model (one model for all when
/// they agree, a model per lane otherwise: a sweep over the body's or the field's numbers), or for
/// megno and lyapunov_max by the ensemble tangent stepper; any other point by
/// evaluate_point_safely. `in_ensemble`, when given, receives the number of points
/// the ensemble stepper advanced, and `runs` the number of ensemble runs (groups of shared
/// settings).
std::vector<PointResult> evaluate_points(const SweepFile& s, std::span<const std::size_t> indices,
                                         std::size_t* in_ensemble = nullptr,
                                         std::size_t* runs = nullptr);

/// The number of points a worker (a thread of run_sweep, a rank under MPI) takes at once, of
/// `count` points left for `workers` workers: one for a sweep evaluated point by point (dynamic
/// balancing point by point); for an ensemble sweep a quarter of an equal share (about four
/// batches per worker, to balance points of different cost), at most 256, rounded up to whole
/// blocks of the SIMD kernel (a block costs about the same whether its lanes are full or not).
std::size_t batch_size(const SweepFile& s, std::size_t count, int workers);

/// The results of a batch of points, in order: evaluate_points for an ensemble sweep,
/// evaluate_point_safely point by point otherwise (each bit-identical to evaluate_point_safely).
std::vector<PointResult> evaluate_batch(const SweepFile& s, std::span<const std::size_t> indices);

}  // namespace newtop::sweep
