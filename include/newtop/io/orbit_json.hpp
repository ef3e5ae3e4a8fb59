#pragma once
/// \file
/// JSON and CSV of the orbit analyses (docs/orbit.md §6–§8): the keys of `newtop equilibria` and
/// `newtop stability` on an orbit scenario and of `newtop stability --diagram debra-delp`, without
/// the scenario's own description (the program adds "model").

#include <ostream>

#include "newtop/io/json.hpp"
#include "newtop/orbit/orbit_equilibria.hpp"
#include "newtop/orbit/orbit_reports.hpp"

namespace newtop::io {

/// eigenvalues ([re, im] pairs), max_real_part, linearly_stable, lyapunov_stable (true where the
/// Jacobi integral is a strict minimum on the leaf, false where unstable, null where only
/// gyroscopic) and verdict: the keys of the fixed-centre `stability` report.
Json to_json(const RelativeSpectrum& spectrum);
/// {"equilibria": [{number, gamma, normal, lvlh_quaternion, roll_pitch_yaw, jacobi, residual, …
/// stability keys}], "count", "lyapunov", "gyroscopic", "unstable"}
Json to_json(const RelativeEquilibriumSet& set);
/// The stability keys, characteristic_polynomial, omega, gamma, normal, jacobi, residual.
Json to_json(const RelativeStabilityReport& report);
/// {"diagram", "parameters", "points", "counts", "disagreements_with_closed_form"}
Json to_json(const DebraDelpDiagram& diagram);
/// k_R,k_Y,region,closed_form,boundary,max_real_part — one row per point.
void write_csv(std::ostream& os, const DebraDelpDiagram& diagram);

}  // namespace newtop::io
