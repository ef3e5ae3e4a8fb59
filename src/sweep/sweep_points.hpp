#pragma once
// Internal: the checks of every point of a sweep, before any work (sweep_points.cpp).

#include "newtop/sweep/sweep.hpp"

namespace newtop::sweep {

/// Builds the scenario of every point and checks that each quantity applies to it (a stability
/// quantity needs a fixed point); fills s.input_files. Throws InputError naming the point.
void check_points(SweepFile& s);

}  // namespace newtop::sweep
