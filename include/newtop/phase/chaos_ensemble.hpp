#pragma once
/// \file
/// The chaos indicators of many starts at once: Taylor's method with one tangent vector per
/// trajectory in SIMD lanes (newtop/integrate/taylor_ensemble.hpp), the indicators accumulated per
/// trajectory by ChaosIndicators. Each result is the bits of chaos(model, x0, {.method =
/// MethodSettings("taylor", 0, abs_tol, rel_tol), .t0 = t0, .t_end = t1, .options = options}) on
/// that start alone.

#include <span>
#include <vector>

#include "newtop/integrate/ensemble.hpp"
#include "newtop/phase/chaos.hpp"

namespace newtop::phase {

/// MEGNO, λ_max and FLI of each start states[i] on models[i] (or models[0] for all) from t0 to t1,
/// with the outcome of its run (indicators of a run that did not finish are those up to where it
/// stopped). Throws InputError before any work as chaos would (tolerances, times, options,
/// states) and for a number of models other than 1 or states.size().
std::vector<ChaosResult> taylor_chaos_ensemble(std::span<const QuadraticModel> models,
                                               std::span<const State> states, double t0, double t1,
                                               double abs_tol, double rel_tol,
                                               const IntegrateOptions& options = {},
                                               SimdPath path = best_simd_path());

}  // namespace newtop::phase
