#pragma once
// The step of the ensemble stepper as a program of stages (ensemble_kernel.hpp), and the kernel of
// a path; private to src/integrate (ensemble.cpp, ensemble_lanes.cpp).

#include <vector>

#include "ensemble_kernel.hpp"
#include "newtop/integrate/ensemble.hpp"

namespace newtop::detail {

/// One step's stages, with the constants computed as run_step and the flows of splitting.hpp
/// compute them from the frame f; with `per_lane`, the times the lanes' constants multiply
/// (EnsembleStage), f then giving only the program's form (gyrostat_ref).
std::vector<EnsembleStage> ensemble_step_program(const std::vector<double>& a,
                                                 const std::vector<double>& b, FreeBodySplit split,
                                                 const SplitFrame& f, double h, bool per_lane);

/// Runs the task on the kernel of the path.
void ensemble_run(SimdPath path, const EnsembleTask& task);

}  // namespace newtop::detail
