#pragma once
/// \file
/// The run settings of an orbit scenario (docs/orbit.md §5, §12): its [integrate] section
/// overridden as on the command line (`--method`, `--step`, `--tol`, `--t-end`), the rules of
/// resolve_method and resolve_t_end for the orbit's methods. The program and the Python module call
/// these.

#include "newtop/integrate/method_settings.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::io {

/// The method to run on an orbit: `method` or the file's method if given; otherwise a step selects
/// the default splitting method (splitting6) and a tolerance the orbit's adaptive method (rkf78);
/// the override's step or tolerance wins over the file's. Tolerance `tol` sets both absolute and
/// relative tolerance. Throws InputError naming `method` for a method that does not run on an
/// orbit, `step` or `tol` when the chosen method lacks it (validate_orbit_method). `split` is not
/// read here (the caller refuses it on an orbit).
MethodSettings resolve_method(const OrbitScenario& s, const IntegrateOverrides& o);

/// t_end from the override or the file: finite and > t0, else InputError naming t_end.
double resolve_t_end(const OrbitScenario& s, const IntegrateOverrides& o);

}  // namespace newtop::io
