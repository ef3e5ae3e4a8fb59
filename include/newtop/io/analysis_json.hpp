#pragma once
/// \file
/// The JSON of the analyses' results, as the command line prints them (docs/cli.md): one
/// `to_json` overload per result type.

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/stability_report.hpp"
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

}  // namespace newtop::io
