#pragma once
/// \file
/// The two-parameter stability diagram of a spin about a principal axis (`newtop stability
/// --scan`, docs/cli.md) run on the sweep layer's threads: every point is computed from its own
/// parameters, independently of the others, so the diagram is the same bits for any thread count.

#include "newtop/analysis/stability_spin.hpp"
#include "newtop/sweep/sweep.hpp"

namespace newtop::sweep {

/// The spin's stability (spin_stability_at) about `axis` at every point of first × second, the
/// axes' keys parameters omega, lambda, A, B or C; Ω = omega where neither axis is omega.
/// `threads` 0: OpenMP's default. Throws InputError for an unknown key, an empty axis, more than
/// io::kMaxGridPoints points or a non-finite value.
StabilityGrid stability_grid(const QuadraticModel& model, int axis, double omega, const Axis& first,
                             const Axis& second, int threads = 0);

}  // namespace newtop::sweep
