#pragma once
/// \file
/// The JSON of the analyses' results, as the command line prints them (docs/cli.md): one
/// `to_json` overload per result type.

#include <ostream>
#include <vector>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/stability_report.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/io/json.hpp"

namespace newtop::io {

/// eigenvalues ([re, im] each), max_real_part, linearly_stable, lyapunov_stable,
/// threshold_omega_formula, threshold_omega_numeric, axis, axis_class, omega, gamma, residual,
/// polish {residual_given, correction, iterations} (null where absent).
Json to_json(const StabilityReport& r, const Body& body);

/// equilibria [{index, gamma, kappa, potential, type, hessian_eigenvalues[, staude_generator,
/// staude_residual]}], count, every_orientation, circles, minima, saddles, maxima, degenerate,
/// count_rule.
Json to_json(const EquilibriumSet& set);

/// The stability along Ω (scan_omega): [{omega, max_real_part, linearly_stable,
/// lyapunov_stable (null: inconclusive)}].
Json to_json(const std::vector<ScanPoint>& scan);

/// The CSV `omega,max_real_part,linearly_stable,energy_casimir_stable` of scan_omega, booleans
/// 1/0: energy_casimir_stable = 1 where the energy–Casimir test proves Lyapunov stability, 0 with
/// linearly_stable = 1 where it is inconclusive (docs/cli.md).
void write_csv(std::ostream& os, const std::vector<ScanPoint>& scan);

/// The CSV `P1,P2,max_real_part,verdict` of a two-parameter diagram, verdict stable, unstable or
/// nonphysical (max_real_part nan there), the second parameter varying fastest.
void write_csv(std::ostream& os, const StabilityGrid& grid);

}  // namespace newtop::io
